// Skin weights and joint regressor of the demo body.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/demo/demo_body_internal.h"
#include "core/math/libm.h"

namespace smpl {
namespace demo {
namespace {

V3 row(const Eigen::MatrixXd& m, int i) { return {m(i, 0), m(i, 1), m(i, 2)}; }

// Softness of the weights (metres of part distance per e-fold): about 5 cm
// of blending on either side of an elbow, wider on the torso.
constexpr double kSkinFalloff = 0.012;
// Influences below this are dropped, so rows stay sparse like SMPL's.
constexpr double kMinWeight = 5e-4;

}  // namespace

Eigen::MatrixXd skinWeights(const Rig& rig, const Eigen::MatrixXd& vertices) {
  // A vertex follows the parts whose surface it lies on: weight falls off
  // with the distance to each part beyond the nearest one. Part distance,
  // unlike bone distance, keeps the wide torso off the arm bones.
  const int n = static_cast<int>(vertices.rows());
  Eigen::MatrixXd w(n, kNumJoints);
  for (int i = 0; i < n; ++i) {
    double d[kNumJoints], best = 1e9;
    for (int k = 0; k < kNumJoints; ++k)
      best = std::min(best, d[k] = partDistance(rig.parts[k], row(vertices, i)));
    double sum = 0;
    for (int k = 0; k < kNumJoints; ++k) sum += w(i, k) = libm::exp(-(d[k] - best) / kSkinFalloff);
    for (int k = 0; k < kNumJoints; ++k) w(i, k) = w(i, k) / sum < kMinWeight ? 0.0 : w(i, k);
    w.row(i) /= w.row(i).sum();
  }
  return w;
}

namespace {

// Exponential tilting: w_i = g_i exp(lambda . (p_i - J)) / Z with lambda
// chosen by Newton's method so that sum w_i p_i = J. Weights stay positive
// and close to the Gaussian prior g; exact whenever J is inside the hull.
Eigen::VectorXd tiltToJoint(const std::vector<V3>& pts, const Eigen::VectorXd& prior, V3 joint) {
  Eigen::Vector3d lambda = Eigen::Vector3d::Zero();
  Eigen::VectorXd w(prior.size());
  for (int it = 0; it < 30; ++it) {
    for (int i = 0; i < w.size(); ++i) {
      const V3 d = pts[i] - joint;
      w[i] = prior[i] * libm::exp(lambda.x() * d.x + lambda.y() * d.y + lambda.z() * d.z);
    }
    w /= w.sum();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int i = 0; i < w.size(); ++i) {
      const Eigen::Vector3d d(pts[i].x - joint.x, pts[i].y - joint.y, pts[i].z - joint.z);
      mean += w[i] * d;
      cov += w[i] * d * d.transpose();
    }
    cov -= mean * mean.transpose();
    if (mean.norm() < 1e-10) break;
    lambda -= (cov + 1e-9 * Eigen::Matrix3d::Identity()).ldlt().solve(mean);
  }
  return w;
}

}  // namespace

Eigen::SparseMatrix<double, Eigen::RowMajor> jointRegressor(const Rig& rig,
                                                            const Eigen::MatrixXd& vertices) {
  // Each joint is a weighted mean of the surface around it (the vertices
  // within 2.5 local radii), so J(beta) follows the shaped surface.
  std::vector<Eigen::Triplet<double>> triplets;
  const int n = static_cast<int>(vertices.rows());
  for (int k = 0; k < kNumJoints; ++k) {
    const V3 joint = rig.joints[k];
    // Local body radius: the distance to the nearest surface point.
    double nearest = 1e9;
    for (int i = 0; i < n; ++i) nearest = std::min(nearest, length(row(vertices, i) - joint));
    const double cutoff = std::max(2.5 * nearest, 0.05), sigma = 0.5 * cutoff;
    std::vector<V3> pts;
    std::vector<int> ids;
    std::vector<double> prior;
    for (int i = 0; i < n; ++i) {
      const double r = length(row(vertices, i) - joint);
      if (r > cutoff) continue;
      pts.push_back(row(vertices, i));
      ids.push_back(i);
      prior.push_back(libm::exp(-0.5 * r * r / (sigma * sigma)));
    }
    const Eigen::VectorXd w =
        tiltToJoint(pts, Eigen::Map<Eigen::VectorXd>(prior.data(), prior.size()), joint);
    const double kept = (w.array() >= 1e-6).select(w, 0.0).sum();
    for (size_t i = 0; i < ids.size(); ++i)
      if (w[i] >= 1e-6) triplets.emplace_back(k, ids[i], w[i] / kept);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> reg(kNumJoints, n);
  reg.setFromTriplets(triplets.begin(), triplets.end());
  return reg;
}

}  // namespace demo
}  // namespace smpl
