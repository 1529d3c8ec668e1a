// The writer table (writer.h): one row per output format.
#include "writers/writer.h"

#include <algorithm>
#include <cctype>

#include "writers/bvh/bvh_writer.h"
#include "writers/fbx/fbx_writer.h"
#include "writers/gltf/gltf_writer.h"
#include "writers/mjcf/mjcf_writer.h"
#include "writers/usd/usd_writer.h"

namespace smpl {
namespace {

bool endsWithNoCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

// `bin` and the splices in file order: one walk for both forms of a tail.
std::vector<ByteSpan> partsOf(const std::string& bin, const std::vector<Writer::Splice>& splices) {
  std::vector<ByteSpan> parts;
  size_t from = 0;
  for (const Writer::Splice& s : splices) {
    parts.push_back({bin.data() + from, s.at - from});
    parts.push_back(s.bytes);
    from = s.at;
  }
  parts.push_back({bin.data() + from, bin.size() - from});
  return parts;
}

}  // namespace

std::vector<ByteSpan> Writer::Files::tailParts() const { return partsOf(tail, splices); }

size_t Writer::Files::size() const {
  size_t n = bytes.size() + tail.size();
  for (const Splice& s : splices) n += s.bytes.size;
  return n;
}

std::string withSplices(const std::string& bin, const std::vector<Writer::Splice>& splices) {
  std::string out;
  out.reserve(bin.size());
  for (const ByteSpan& part : partsOf(bin, splices))
    out.append(static_cast<const char*>(part.data), part.size);
  return out;
}

namespace {

std::deque<WriterFormat>& table() {
  static std::deque<WriterFormat> rows = [] {
    const std::vector<std::string> gltf_options = {
        "--corrective-epsilon", "--quantize-morphs", "--draco", "--meshopt",
        "--quantize-animation", "--skeleton-names"};
    std::vector<std::string> gltf_text_options = gltf_options;
    gltf_text_options.push_back("--gltf-embed");
    return std::deque<WriterFormat>{
        {"glb", {".glb"}, gltf_options, true, true, false, &gltfWriter()},
        {"gltf", {".gltf"}, gltf_text_options, true, false, true, &gltfWriter()},
        {"fbx",
         {".fbx"},
         {"--fbx-units", "--fbx-version", "--fbx-compress-level", "--skeleton-names"},
         true,
         true,
         false,
         &fbxWriter()},
        {"bvh",
         {".bvh"},
         {"--bvh-units", "--skeleton-names"},
         /*needs_mesh=*/false,
         true,
         false,
         &bvhWriter(),
         /*single_clip=*/true},
        {"mjcf",
         {".xml"},
         {"--density", "--mjcf-joints", "--mjcf-geoms", "--mjcf-motors"},
         /*needs_mesh=*/true,
         true,
         false,
         &mjcfWriter(),
         /*single_clip=*/true,
         /*animated=*/true,
         /*motion_file=*/".qpos.npz"},
        {"usda",
         {".usda", ".usd"},
         {},
         /*needs_mesh=*/true,
         false,
         false,
         &usdaWriter(),
         /*single_clip=*/true},
        {"usdz",
         {".usdz"},
         {},
         /*needs_mesh=*/true,
         true,
         false,
         &usdzWriter(),
         /*single_clip=*/true},
    };
  }();
  return rows;
}

}  // namespace

const std::deque<WriterFormat>& writerFormats() { return table(); }

const WriterFormat* writerFormatForPath(const std::string& path) {
  for (const WriterFormat& row : table())
    for (const std::string& ext : row.extensions)
      if (endsWithNoCase(path, ext)) return &row;
  return nullptr;
}

const WriterFormat* writerFormatByName(const std::string& name) {
  for (const WriterFormat& row : table())
    if (row.name == name) return &row;
  return nullptr;
}

const Writer* writerForPath(const std::string& path) {
  const WriterFormat* row = writerFormatForPath(path);
  return row ? row->writer : nullptr;
}

std::string writerExtensionList(const std::string& last) {
  std::vector<std::string> all;
  for (const WriterFormat& row : table())
    all.insert(all.end(), row.extensions.begin(), row.extensions.end());
  std::string text;
  for (size_t i = 0; i < all.size(); ++i)
    text += (i == 0 ? "" : i + 1 == all.size() ? last : ", ") + all[i];
  return text;
}

ScopedWriterFormat::ScopedWriterFormat(WriterFormat row) { table().push_back(std::move(row)); }

ScopedWriterFormat::~ScopedWriterFormat() { table().pop_back(); }

}  // namespace smpl
