// How much a compact glTF encoding (sparse, quantized, Draco) changes the
// body: decode the written file (tinygltf's loader, then this file's sparse
// expansion and dequantisation, and Draco for the base mesh), and compare the
// pre-skinning mesh base + sum_n w_n(f) d_n with the exact asset's over a
// fixed pose set (core/pose_sampler.h, seeded). w_n(f) = scale * f[feature] +
// offset from each side's own metadata (max(0, .) for "rectified" entries) (so a scale folded into
// the weights, morph_scales.h, is accounted for); targets without a corrective entry use their rest
// weight. Linear blend skinning with weights summing to 1 moves an offset by at most its length, so
// the result bounds the added vertex error of every posed vertex.
//
//   Result<DecodedMorphs> file = decodeMorphs(glb_bytes);
//   double metres = morphError(*file, asset);  // max over 32 poses and vertices
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

struct DecodedMorphs {
  Eigen::MatrixXf positions;                  // V x 3 base mesh as a reader sees it
  std::vector<Eigen::MatrixXf> deltas;        // per target, V x 3, dense, in metres-per-weight
  std::vector<std::string> names;             // mesh.extras.targetNames
  std::vector<double> rest_weights;           // mesh.weights
  std::vector<CorrectiveLayout> correctives;  // asset.extras.smpl.correctives
};

// GLB or .gltf bytes -> the first mesh's base positions and morph targets.
Result<DecodedMorphs> decodeMorphs(const std::string& bytes);

// Max over `num_poses` poses (seeded) and vertices of |decoded - exact| offset.
// `exact` is the asset given to the writer; its vertex count must match.
Result<double> morphError(const DecodedMorphs& file, const Asset& exact, int num_poses = 32,
                          uint64_t seed = 1);

}  // namespace smpl
