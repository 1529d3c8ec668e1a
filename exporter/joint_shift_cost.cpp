#include "exporter/joint_shift_cost.h"

#include <algorithm>

namespace smpl {

Eigen::MatrixXd skinTranslations(const std::vector<int>& parents, const Eigen::MatrixXd& x,
                                 const Rotations& local, const Eigen::Matrix3d& up) {
  const int k = static_cast<int>(parents.size());
  std::vector<Eigen::Matrix3d> rw(k);
  Eigen::MatrixXd t(k, 3), a(k, 3);
  for (int j = 0; j < k; ++j) {
    const int p = parents[j];
    if (p < 0) {
      rw[j] = local[j];
      t.row(j) = (up * x.row(j).transpose()).transpose();
    } else {
      rw[j] = rw[p] * local[j];
      t.row(j) = t.row(p) + (rw[p] * (x.row(j) - x.row(p)).transpose()).transpose();
    }
    a.row(j) = t.row(j) - (rw[j] * x.row(j).transpose()).transpose();
  }
  return a;
}

double maxSkinError(const SkinnedMesh& mesh, const Eigen::MatrixXd& da) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < mesh.joints.rows(); ++i) {
    Eigen::RowVector3d e = Eigen::RowVector3d::Zero();
    for (Eigen::Index m = 0; m < mesh.joints.cols(); ++m)
      e += double(mesh.weights(i, m)) * da.row(mesh.joints(i, m));
    worst = std::max(worst, e.norm());
  }
  return worst;
}

double jointShiftCost(const Skeleton& s, const SkinnedMesh& mesh, const Eigen::MatrixXd& delta,
                      const Rotations& local, const Eigen::Matrix3d& up) {
  const Eigen::MatrixXd da = skinTranslations(s.parents, s.rest_world + delta, local, up) -
                             skinTranslations(s.parents, s.rest_world, local, up);
  return maxSkinError(mesh, da);
}

}  // namespace smpl
