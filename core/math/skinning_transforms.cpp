#include "core/math/skinning_transforms.h"

namespace smpl {

std::vector<Affine> skinningTransforms(const BodyModel& model, const Eigen::MatrixXd& joints,
                                       const Rotations& r) {
  const int k_count = model.numJoints();
  std::vector<Eigen::Matrix3d> rot(k_count);
  std::vector<Eigen::Vector3d> trans(k_count);
  std::vector<Affine> a(k_count);
  for (int k = 0; k < k_count; ++k) {
    const int p = model.parents[k];
    const Eigen::Vector3d j = joints.row(k).transpose();
    if (p < 0) {
      rot[k] = r[k];
      trans[k] = j;
    } else {
      rot[k] = rot[p] * r[k];
      trans[k] = rot[p] * (j - joints.row(p).transpose()) + trans[p];
    }
    a[k].leftCols<3>() = rot[k];
    a[k].col(3) = trans[k] - rot[k] * j;
  }
  return a;
}

}  // namespace smpl
