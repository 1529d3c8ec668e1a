// Internal to the glTF writer: EXT_meshopt_compression (--meshopt). While the
// model is built, each bufferView that meshopt can take is marked with its
// codec (markMeshopt); compressMeshoptViews then replaces the marked views'
// bytes in buffer 0 by meshopt's encoding (meshoptimizer's vertex and index
// codecs, Debian's libmeshoptimizer), moves the views themselves into a
// fallback buffer 1 that holds no bytes, and returns the JSON that
// tinygltf 2.7 cannot write (bufferView extensions, the fallback buffer),
// spliced in by spliceMeshoptJson after serialisation.
//
// Spec: KhronosGroup/glTF extensions/2.0/Vendor/EXT_meshopt_compression.
// ATTRIBUTES: byteStride a multiple of 4, at most 256, byteLength = count *
// byteStride; INDICES: 2- or 4-byte indices (the triangle list, kept exactly:
// the TRIANGLES codec may rotate corners, so the view would not decode to the
// same bytes). Filters:
// QUATERNION (stride 8: the view holds meshopt_encodeFilterQuat's output,
// decoded to normalised int16 x, y, z, w). Views meshopt cannot take (sparse
// indices, 6-byte int16 triples, Draco's blob) stay uncompressed in buffer 0.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/result.h"
#include "writers/gltf/gltf_buffer.h"

namespace smpl {

// With b.meshopt, marks bufferView `view` for compression: `element_size` bytes per element
// (ATTRIBUTES: multiple of 4, <= 256; INDICES: 2 or 4, the index size).
void markMeshopt(GltfBuild& b, int view, MeshoptMode mode, int element_size,
                 MeshoptFilter filter = MeshoptFilter::None);

// meshopt_encodeFilterQuat of `count` unit quaternions (x, y, z, w floats) with
// 16-bit components: the bytes of a QUATERNION-filtered view (8 per quaternion).
std::vector<int16_t> quaternionFilter(const std::vector<float>& xyzw);

struct MeshoptJson {
  nlohmann::json view_extensions = nlohmann::json::object();  // view index -> extension object
  size_t fallback_bytes = 0;                                  // byteLength of buffer 1
};

// Compresses the marked views (in view order, deterministic) and rewrites
// b.bin; no marked view: nothing changes and the result is empty.
Result<MeshoptJson> compressMeshoptViews(GltfBuild& b);

// Adds the bufferView extensions and the fallback buffer to the serialised
// JSON (GLB chunk: compact; .gltf: tinygltf's indent of 2).
Status spliceMeshoptJson(std::string& json, const MeshoptJson& meshopt, bool pretty);

}  // namespace smpl
