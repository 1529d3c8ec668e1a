#include "core/math/corrective_refit.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <thread>

#include "core/math/motion_poses.h"
#include "core/math/pose_sampler.h"
#include "core/math/skinning_transforms.h"

namespace smpl {
namespace {

// Poses with what every vertex needs of them.
struct PoseSet {
  std::vector<std::vector<Affine>> transforms;  // [pose][joint]
  Eigen::MatrixXd features;                     // P x T
};

PoseSet poseSet(const BodyModel& model, const ShapedBody& body,
                const std::vector<Eigen::VectorXd>& poses) {
  PoseSet s;
  s.features.resize(model.numPoseFeatures(), Eigen::Index(poses.size()));
  for (size_t p = 0; p < poses.size(); ++p) {
    const Rotations r = rotationsFromAxisAngle(poses[p]);
    s.features.col(Eigen::Index(p)) = poseFeatures(r);
    s.transforms.push_back(skinningTransforms(model, body.joints, r));
  }
  return s;
}

// The features a vertex's refit may change: the 9 of every joint with a
// non-zero model weight and (options.parents) of its parent; the root has none.
std::vector<Eigen::Index> featuresOf(const BodyModel& model, Eigen::Index i, bool parents) {
  std::vector<bool> use(size_t(model.numJoints()), false);
  for (int k = 0; k < model.numJoints(); ++k)
    if (model.weights(i, k) > 0) {
      use[size_t(k)] = true;
      if (parents && model.parents[size_t(k)] >= 0) use[size_t(model.parents[size_t(k)])] = true;
    }
  std::vector<Eigen::Index> features;
  for (int k = 1; k < model.numJoints(); ++k)
    if (use[size_t(k)])
      for (int n = 0; n < 9; ++n) features.push_back(9 * (k - 1) + n);
  return features;
}

// One vertex over one pose set: the pruning error e_p (3 x T) and the
// pruned blend's rotations R_p (T of them).
struct VertexPoses {
  Eigen::Matrix3Xd error;
  std::vector<Eigen::Matrix3d> blend;
};

VertexPoses vertexPoses(const BodyModel& model, const ShapedBody& body, const SparseSkin& skin,
                        const PoseSet& set, Eigen::Index i) {
  const Eigen::Index t_count = set.features.cols();
  const Eigen::Matrix3Xd x = (model.posedirs.middleRows(3 * i, 3) * set.features).colwise() +
                             body.v_shaped.row(i).transpose();
  VertexPoses v;
  v.error.resize(3, t_count);
  v.blend.resize(size_t(t_count));
  for (Eigen::Index p = 0; p < t_count; ++p) {
    const std::vector<Affine>& a = set.transforms[size_t(p)];
    Affine full = Affine::Zero(), pruned = Affine::Zero();
    for (int k = 0; k < model.numJoints(); ++k)
      if (model.weights(i, k) > 0) full += model.weights(i, k) * a[size_t(k)];
    for (Eigen::Index s = 0; s < skin.joints.cols(); ++s)
      if (skin.weights(i, s) > 0) pruned += skin.weights(i, s) * a[size_t(skin.joints(i, s))];
    const Eigen::Vector4d xh = x.col(p).homogeneous();
    v.error.col(p) = (full - pruned) * xh;
    v.blend[size_t(p)] = pruned.leftCols<3>();
  }
  return v;
}

// Mean and max over poses of |e_p - R_p D f_S(p)| (d empty: |e_p|).
std::pair<double, double> poseErrors(const VertexPoses& v, const Eigen::MatrixXd& fs,
                                     const Eigen::MatrixXd& d) {
  double sum = 0.0, worst = 0.0;
  for (Eigen::Index p = 0; p < v.error.cols(); ++p) {
    Eigen::Vector3d r = v.error.col(p);
    if (d.size() > 0) r -= v.blend[size_t(p)] * (d * fs.col(p));
    const double e = r.norm();
    sum += e;
    worst = std::max(worst, e);
  }
  return {v.error.cols() > 0 ? sum / double(v.error.cols()) : 0.0, worst};
}

Eigen::MatrixXd selectRows(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& rows) {
  Eigen::MatrixXd out(Eigen::Index(rows.size()), m.cols());
  for (size_t r = 0; r < rows.size(); ++r) out.row(Eigen::Index(r)) = m.row(rows[r]);
  return out;
}

struct Context {
  const BodyModel& model;
  const ShapedBody& body;
  const SparseSkin& skin;
  const CorrectiveRefitOptions& options;
  PoseSet train, validate;
  Eigen::MatrixXd gram;  // P x P, F F' of the training poses
};

// D_i (3 x |S|) of one vertex, or an empty matrix where the guard keeps the model's deltas.
Eigen::MatrixXd fitVertex(const Context& c, Eigen::Index i,
                          const std::vector<Eigen::Index>& features) {
  if (features.empty()) return Eigen::MatrixXd();  // moved by the root alone: nothing to refit
  const VertexPoses v = vertexPoses(c.model, c.body, c.skin, c.train, i);
  const Eigen::MatrixXd fs = selectRows(c.train.features, features);  // |S| x T
  Eigen::Matrix3Xd z(3, v.error.cols());  // rest-frame targets R_p^{-1} e_p
  for (Eigen::Index p = 0; p < z.cols(); ++p)
    z.col(p) = v.blend[size_t(p)].partialPivLu().solve(v.error.col(p));
  const Eigen::Index s = Eigen::Index(features.size());
  Eigen::MatrixXd h(s, s);
  for (Eigen::Index a = 0; a < s; ++a)
    for (Eigen::Index b = 0; b < s; ++b) h(a, b) = c.gram(features[size_t(a)], features[size_t(b)]);
  const double lambda = c.options.ridge * std::max(h.diagonal().mean(), 1e-12);
  h.diagonal().array() += lambda;
  const Eigen::MatrixXd d = h.ldlt().solve(fs * z.transpose()).transpose();  // 3 x |S|
  if (!c.options.guard) return d;
  const VertexPoses check = vertexPoses(c.model, c.body, c.skin, c.validate, i);
  const Eigen::MatrixXd check_fs = selectRows(c.validate.features, features);
  const auto before = poseErrors(check, check_fs, Eigen::MatrixXd());
  const auto after = poseErrors(check, check_fs, d);
  if (after.first > before.first || after.second > before.second) return Eigen::MatrixXd();
  return d;
}

int nonZero(const Eigen::MatrixXd& m, Eigen::Index i) {
  return int((m.row(i).array() > 0).count());
}

}  // namespace

double CorrectiveRefit::delta(const BodyModel& model, Eigen::Index row, Eigen::Index n) const {
  const int b = block.empty() ? -1 : block[size_t(row / 3)];
  return b < 0 ? model.posedirs(row, n) : rows(3 * b + row % 3, n);
}

Eigen::VectorXd CorrectiveRefit::column(const BodyModel& model, Eigen::Index n) const {
  Eigen::VectorXd col = model.posedirs.col(n);
  for (size_t i = 0; i < block.size(); ++i)
    if (block[i] >= 0) col.segment<3>(3 * Eigen::Index(i)) = rows.col(n).segment<3>(3 * block[i]);
  return col;
}

Eigen::MatrixXd CorrectiveRefit::posedirs(const BodyModel& model) const {
  Eigen::MatrixXd p = model.posedirs;
  for (size_t i = 0; i < block.size(); ++i)
    if (block[i] >= 0) p.middleRows<3>(3 * Eigen::Index(i)) = rows.middleRows<3>(3 * block[i]);
  return p;
}

CorrectiveRefit refitCorrectives(const BodyModel& model, const ShapedBody& body,
                                 const SparseSkin& skin, const CorrectiveRefitOptions& o) {
  CorrectiveRefit refit;
  const Eigen::Index n = model.numVertices();
  std::vector<Eigen::Index> cut;
  for (Eigen::Index i = 0; i < n; ++i)
    if (nonZero(model.weights, i) > nonZero(skin.weights, i)) cut.push_back(i);
  refit.cut = int(cut.size());
  if (cut.empty() || model.numPoseFeatures() == 0) return refit;
  std::vector<Eigen::VectorXd> check =
      sampleMotionPoses(model.joint_names, o.validation_poses, o.validation_seed);
  for (Eigen::VectorXd& pose : samplePoses(model.numJoints(), o.validation_poses,
                                           o.validation_seed + 1, o.validation_scale))
    check.push_back(std::move(pose));
  Context c{model, body, skin, o, {}, {}, {}};
  c.train = poseSet(model, body, sampleMotionPoses(model.joint_names, o.training_poses, o.seed));
  c.validate = poseSet(model, body, check);
  c.gram = c.train.features * c.train.features.transpose();
  std::vector<std::vector<Eigen::Index>> features(cut.size());
  std::vector<Eigen::MatrixXd> deltas(cut.size());
  const int workers = std::max(1, std::min<int>(o.threads, int(cut.size() / 64) + 1));
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w)
    pool.emplace_back([&, w] {
      for (size_t j = size_t(w); j < cut.size(); j += size_t(workers)) {
        features[j] = featuresOf(model, cut[j], o.parents);
        deltas[j] = fitVertex(c, cut[j], features[j]);
      }
    });
  for (std::thread& t : pool) t.join();
  refit.block.assign(size_t(n), -1);
  int blocks = 0;
  for (const Eigen::MatrixXd& d : deltas) blocks += d.size() > 0 ? 1 : 0;
  refit.kept = refit.cut - blocks;
  refit.rows.resize(3 * blocks, model.numPoseFeatures());
  int b = 0;
  for (size_t j = 0; j < cut.size(); ++j) {
    if (deltas[j].size() == 0) continue;
    refit.block[size_t(cut[j])] = b;
    refit.rows.middleRows<3>(3 * b) = model.posedirs.middleRows<3>(3 * cut[j]);
    for (size_t f = 0; f < features[j].size(); ++f)
      refit.rows.block<3, 1>(3 * b, features[j][f]) += deltas[j].col(Eigen::Index(f));
    ++b;
  }
  if (blocks == 0) refit.block.clear();
  return refit;
}

void addRefitCorrection(const BodyModel& model, const ShapedBody& body, const SparseSkin& skin,
                        const CorrectiveRefit& refit, const std::vector<Rotations>& frames,
                        Eigen::MatrixXd* posed) {
  if (refit.empty()) return;
  for (size_t t = 0; t < frames.size(); ++t) {
    const std::vector<Affine> a = skinningTransforms(model, body.joints, frames[t]);
    const Eigen::VectorXd f = poseFeatures(frames[t]);
    for (size_t i = 0; i < refit.block.size(); ++i) {
      const int b = refit.block[i];
      if (b < 0) continue;
      const Eigen::Index v = Eigen::Index(i);
      Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
      for (Eigen::Index s = 0; s < skin.joints.cols(); ++s)
        if (skin.weights(v, s) > 0)
          r += skin.weights(v, s) * a[size_t(skin.joints(v, s))].leftCols<3>();
      const Eigen::Vector3d change =
          (refit.rows.middleRows<3>(3 * b) - model.posedirs.middleRows<3>(3 * v)) * f;
      posed->block<3, 1>(3 * v, Eigen::Index(t)) += r * change;
    }
  }
}

}  // namespace smpl
