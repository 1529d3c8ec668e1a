// The per-joint skinning transforms of one pose, A_k = G_k [I | -J_k]
// (docs/file-contract.md), as 3 x 4 affine matrices in double: what the
// per-vertex fits (skin weights, corrective refit) evaluate linear blend
// skinning with, v' = sum_k w_k A_k [v; 1].
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/body_model.h"
#include "core/math/forward.h"

namespace smpl {

using Affine = Eigen::Matrix<double, 3, 4>;

// K transforms for rest joints `joints` (K x 3, metres) and local rotations `r` (K).
std::vector<Affine> skinningTransforms(const BodyModel& model, const Eigen::MatrixXd& joints,
                                       const Rotations& r);

}  // namespace smpl
