// Output format registry: picks the writer from the output file extension.
#include "plugins/writer.h"

#include <algorithm>
#include <cctype>

#include "plugins/gltf/gltf_writer.h"
#if __has_include("plugins/fbx/fbx_writer.h")
#include "plugins/fbx/fbx_writer.h"
#define SMPL_HAVE_FBX_WRITER 1
#endif

namespace smpl {
namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(), [](char a, char b) {
    return a == std::tolower(static_cast<unsigned char>(b));
  });
}

}  // namespace

const Writer* writerForPath(const std::string& path) {
  if (endsWith(path, ".glb") || endsWith(path, ".gltf")) return &gltfWriter();
#ifdef SMPL_HAVE_FBX_WRITER
  if (endsWith(path, ".fbx")) return &fbxWriter();
#endif
  return nullptr;
}

}  // namespace smpl
