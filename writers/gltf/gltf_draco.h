// Draco (KHR_draco_mesh_compression) for the base mesh of the glTF writer, and
// the decoder the tests and morph_error.h use. Sequential encoding and no
// point deduplication, so decoded point i is vertex i: the morph targets,
// which stay uncompressed accessors, remain aligned with the vertices.
// Quantisation: positions 16 bits over the mesh's bounding cube (error at most
// half a step, extent / 65535 / 2 per component), normals 12 bits, UVs 14 bits;
// joints and weights are GENERIC attributes, stored losslessly.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

// The base mesh's vertex streams, row-major, as the glTF accessors hold them.
struct MeshStreams {
  size_t vertices = 0;
  std::vector<float> positions, normals, uvs;  // 3V, 3V, 2V or empty
  std::vector<std::vector<uint16_t>> joints;   // per set, 4V
  std::vector<std::vector<float>> weights;     // per set, 4V
  bool wide_joints = false;                    // UNSIGNED_SHORT joints (else UNSIGNED_BYTE)
  std::vector<uint32_t> indices;               // 3F
};

constexpr int kDracoPositionBits = 16;

struct DracoBlob {
  std::string bytes;
  std::map<std::string, int> attributes;  // glTF semantic -> Draco unique id
};

// Without Draco (SMPL_NO_DRACO, dracoAvailable() in writer.h) both fail with
// the one-line reason.
Result<DracoBlob> encodeDraco(const MeshStreams& mesh);

// Decodes `bytes`; `attributes` as in the glTF extension. Fills positions,
// normals, uvs (if listed) and indices; checks the point count.
Result<MeshStreams> decodeDraco(const std::string& bytes,
                                const std::map<std::string, int>& attributes,
                                size_t expected_vertices);

}  // namespace smpl
