#include "writers/gltf/gltf_meshopt.h"

#ifndef SMPL_NO_MESHOPT
#include <meshoptimizer.h>
#endif

#include <cstring>
#include <exception>

namespace smpl {
namespace {

const char kExtension[] = "EXT_meshopt_compression";
[[maybe_unused]] const char kNoMeshopt[] =
    "--meshopt: this smpl-export was built without meshoptimizer (the static build: Debian ships "
    "no static libmeshoptimizer); use the Debian package build";

// The view's bytes, encoded: the vertex codec (ATTRIBUTES) or the index sequence codec
// (INDICES: every index kept in place; the TRIANGLES codec may rotate a triangle's corners).
Result<std::string> encodeView(const std::string& bin, const tinygltf::BufferView& view,
                               const MeshoptMark& mark, size_t count) {
#ifdef SMPL_NO_MESHOPT
  (void)bin, (void)view, (void)mark, (void)count;
  return makeError(kNoMeshopt);
#else
  const auto* data = reinterpret_cast<const unsigned char*>(bin.data() + view.byteOffset);
  std::string out;
  size_t size = 0;
  if (mark.mode == MeshoptMode::Attributes) {
    out.resize(meshopt_encodeVertexBufferBound(count, size_t(mark.element_size)));
    size = meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(&out[0]), out.size(), data,
                                      count, size_t(mark.element_size));
  } else {
    std::vector<unsigned int> indices(count);
    unsigned int largest = 0;
    for (size_t i = 0; i < count; ++i) {
      if (mark.element_size == 2) {
        uint16_t v;
        std::memcpy(&v, data + 2 * i, 2);
        indices[i] = v;
      } else {
        std::memcpy(&indices[i], data + 4 * i, 4);
      }
      largest = std::max(largest, indices[i]);
    }
    out.resize(meshopt_encodeIndexSequenceBound(count, size_t(largest) + 1));
    size = meshopt_encodeIndexSequence(reinterpret_cast<unsigned char*>(&out[0]), out.size(),
                                       indices.data(), count);
  }
  if (size == 0) return makeError("glTF writer: meshopt could not encode bufferView");
  out.resize(size);
  return out;
#endif
}

nlohmann::json extensionOf(const MeshoptMark& mark, size_t offset, size_t length, size_t count) {
  nlohmann::json e = {{"buffer", 0},
                      {"byteOffset", offset},
                      {"byteLength", length},
                      {"byteStride", mark.element_size},
                      {"count", count},
                      {"mode", mark.mode == MeshoptMode::Attributes ? "ATTRIBUTES" : "INDICES"}};
  if (mark.filter == MeshoptFilter::Quaternion) e["filter"] = "QUATERNION";
  return e;
}

}  // namespace

void markMeshopt(GltfBuild& b, int view, MeshoptMode mode, int element_size, MeshoptFilter filter) {
  if (b.meshopt) b.meshopt_marks.push_back({view, mode, element_size, filter});
}

std::vector<int16_t> quaternionFilter(const std::vector<float>& xyzw) {
  std::vector<int16_t> out(xyzw.size(), 0);
#ifndef SMPL_NO_MESHOPT
  if (!xyzw.empty()) meshopt_encodeFilterQuat(out.data(), xyzw.size() / 4, 8, 16, xyzw.data());
#endif
  return out;
}

bool meshoptAvailable() {
#ifdef SMPL_NO_MESHOPT
  return false;
#else
  return true;
#endif
}

Result<MeshoptJson> compressMeshoptViews(GltfBuild& b) {
  MeshoptJson result;
  if (b.meshopt_marks.empty()) return result;
  std::vector<const MeshoptMark*> mark_of(b.model.bufferViews.size(), nullptr);
  for (const MeshoptMark& m : b.meshopt_marks) mark_of[size_t(m.view)] = &m;
  std::string bin;
  bin.reserve(b.bin.size());
  for (size_t v = 0; v < b.model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = b.model.bufferViews[v];
    bin.resize(align4(bin.size()), '\0');
    const MeshoptMark* mark = mark_of[v];
    if (!mark || view.byteLength == 0) {  // stays in buffer 0, uncompressed
      bin.append(b.bin, view.byteOffset, view.byteLength);
      view.byteOffset = bin.size() - view.byteLength;
      continue;
    }
    const size_t count = view.byteLength / size_t(mark->element_size);
    Result<std::string> encoded = encodeView(b.bin, view, *mark, count);
    if (!encoded) return encoded.error();
    result.view_extensions[std::to_string(v)] =
        extensionOf(*mark, bin.size(), encoded->size(), count);
    bin += *encoded;
    result.fallback_bytes = align4(result.fallback_bytes);
    view.buffer = 1;
    view.byteOffset = result.fallback_bytes;
    result.fallback_bytes += view.byteLength;
  }
  b.bin.swap(bin);
  return result;
}

Status spliceMeshoptJson(std::string& json, const MeshoptJson& meshopt, bool pretty) {
  if (meshopt.view_extensions.empty()) return Status::success();
  nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
  if (doc.is_discarded() || !doc.contains("bufferViews") || !doc.contains("buffers"))
    return makeError("glTF writer: cannot add EXT_meshopt_compression to the serialised JSON");
  for (const auto& [index, extension] : meshopt.view_extensions.items())
    doc["bufferViews"][size_t(std::stoul(index))]["extensions"][kExtension] = extension;
  doc["buffers"].push_back({{"byteLength", meshopt.fallback_bytes},
                            {"extensions", {{kExtension, {{"fallback", true}}}}}});
  try {  // the same strings tinygltf has just written: valid UTF-8
    json = doc.dump(pretty ? 2 : -1);
  } catch (const std::exception& e) {
    return makeError(std::string("glTF writer: cannot serialise EXT_meshopt_compression: ") +
                     e.what());
  }
  return Status::success();
}

}  // namespace smpl
