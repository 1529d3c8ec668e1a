#include "tools/bench/synthetic_model.h"

#include <cmath>

#include "core/joint_names.h"
#include "core/math/pose_sampler.h"

namespace smpl {
namespace {

// SMPL-family parents by family (same tables as the model files).
std::vector<int> parentsFor(ModelKind kind) {
  std::vector<int> p = {-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19};
  auto hand = [&](int wrist) {
    for (int chain = 0; chain < 5; ++chain) {
      const int base = static_cast<int>(p.size());
      p.insert(p.end(), {wrist, base, base + 1});
    }
  };
  if (kind == ModelKind::Smpl) p.insert(p.end(), {20, 21});
  if (kind == ModelKind::SmplX) p.insert(p.end(), {15, 15, 15});
  if (kind != ModelKind::Smpl) hand(20), hand(21);
  return p;
}

}  // namespace

BodyModel syntheticModel(ModelKind kind, int n, int num_betas, int num_expressions, uint64_t seed) {
  BodyModel m;
  m.kind = kind;
  m.name = std::string("synthetic-") + modelKindName(kind);
  m.parents = parentsFor(kind);
  m.joint_names = canonicalJointNames(kind);
  const int k = static_cast<int>(m.parents.size());
  // Random numbers come from the pose sampler's generator: uniform in [-1, 1].
  Eigen::MatrixXd joints(k, 3);
  std::vector<Eigen::VectorXd> steps = samplePoses(k, 1, seed, 1.0);
  joints.row(0) << 0, 0.9, 0;
  for (int j = 1; j < k; ++j)
    joints.row(j) =
        joints.row(m.parents[j]) + 0.15 * steps[0].segment<3>(3 * j).normalized().transpose();
  std::vector<Eigen::VectorXd> r = samplePoses(n, 4, seed + 1, 1.0);  // 12n uniforms
  m.v_template.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    const int j = i % k;
    m.v_template.row(i) = joints.row(j) + 0.08 * r[0].segment<3>(3 * i).transpose();
  }
  m.weights = Eigen::MatrixXd::Zero(n, k);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j)
      m.weights(i, j) = std::exp(-(m.v_template.row(i) - joints.row(j)).squaredNorm() / 0.01);
    m.weights.row(i) /= m.weights.row(i).sum();
  }
  Eigen::MatrixXd dense_regressor = Eigen::MatrixXd::Zero(k, n);
  for (int j = 0; j < k; ++j) {
    for (int i = j; i < n; i += k) dense_regressor(j, i) = 1.0;
    dense_regressor.row(j) /= dense_regressor.row(j).sum();
  }
  m.j_regressor = dense_regressor.sparseView();
  m.faces.resize(n - 2, 3);
  for (int f = 0; f < n - 2; ++f) m.faces.row(f) << f, f + 1, f + 2;
  const int p = 9 * (k - 1);
  m.posedirs.resize(3 * n, p);
  std::vector<Eigen::VectorXd> pr = samplePoses(n * p, 1, seed + 2, 1.0);  // 3np uniforms
  for (int col = 0; col < p; ++col) {
    const int j = col / 9 + 1, parent = m.parents[j];
    for (int i = 0; i < n; ++i) {
      const double local = 0.02 * (m.weights(i, j) + m.weights(i, parent)) + 2e-5;
      for (int c = 0; c < 3; ++c)
        m.posedirs(3 * i + c, col) = local * pr[0][(static_cast<int64_t>(col) * n + i) * 3 + c];
    }
  }
  std::vector<Eigen::VectorXd> sr =
      samplePoses(n * (num_betas + num_expressions), 1, seed + 3, 1.0);
  Eigen::MatrixXd dirs =
      0.01 * Eigen::Map<Eigen::MatrixXd>(sr[0].data(), 3 * n, num_betas + num_expressions);
  m.shapedirs = dirs.leftCols(num_betas);
  m.exprdirs = dirs.rightCols(num_expressions);
  return m;
}

}  // namespace smpl
