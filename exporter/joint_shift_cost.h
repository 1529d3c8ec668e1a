// What fixed joints cost. The exported skeleton is the rest shape's (joints
// J = J_regressor v_shaped); where the published math regresses the joints
// from a template that also moves with something animated (DMPL soft tissue,
// SMPL-X expressions: J' = J + delta), a frame's skin transforms differ in
// their translations only: A'_k - A_k = [0 | a'_k - a_k] with
// a_k = t_k - Rw_k J_k (t_k, Rw_k: joint k's world translation and rotation
// for the frame's local rotations). The vertex error is |sum_m w_im (a'_m - a_m)|
// over the exported (pruned) skin.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/math/forward.h"
#include "exporter/asset.h"

namespace smpl {

// a_k (K x 3) for rest joints `x` (K x 3) and the frame's local rotations;
// the root's local[0] includes the up-axis rotation `up`, so its translation
// is up * x_0 (the root translation itself cancels in differences).
Eigen::MatrixXd skinTranslations(const std::vector<int>& parents, const Eigen::MatrixXd& x,
                                 const Rotations& local, const Eigen::Matrix3d& up);

// max_i |sum_m w_im da_{joint_im}| over the asset's skin (metres).
double maxSkinError(const SkinnedMesh& mesh, const Eigen::MatrixXd& da);

// The vertex error (metres) of keeping `skeleton`'s joints when the published
// joints are rest_world + delta (K x 3) at this frame.
double jointShiftCost(const Skeleton& skeleton, const SkinnedMesh& mesh,
                      const Eigen::MatrixXd& delta, const Rotations& local,
                      const Eigen::Matrix3d& up);

}  // namespace smpl
