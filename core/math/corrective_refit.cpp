#include "core/math/corrective_refit.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <atomic>
#include <map>
#include <string>
#include <thread>

#include "core/math/fixed_order_gemm.h"
#include "core/math/motion_poses.h"
#include "core/math/pose_sampler.h"
#include "core/math/skinning_transforms.h"
#include "core/parallel.h"

namespace smpl {
namespace {

constexpr Eigen::Index kBlock = 32;  // vertices per block: their products are GEMMs

// Poses with what every vertex needs of them. The per-block products (the
// pruning errors, the blends, the ridge regression's map and the guard's
// correction) run in float (fixed order, twice the lanes): their rounding,
// about 1e-7 of a metre, is far below the millimetre errors the refit
// corrects. The Gram matrix and its factor stay double.
struct PoseSet {
  Eigen::MatrixXd features;      // P x T
  Eigen::MatrixXf features32;    // features in float
  Eigen::MatrixXf transforms32;  // K x 12T: A_k(p) row by row at columns 12p + 4r + c
};

PoseSet poseSet(const BodyModel& model, const ShapedBody& body,
                const std::vector<Eigen::VectorXd>& poses) {
  PoseSet s;
  const Eigen::Index t_count = Eigen::Index(poses.size());
  s.features.resize(model.numPoseFeatures(), t_count);
  s.transforms32.resize(model.numJoints(), 12 * t_count);
  for (Eigen::Index p = 0; p < t_count; ++p) {
    const Rotations r = rotationsFromAxisAngle(poses[size_t(p)]);
    s.features.col(p) = poseFeatures(r);
    const std::vector<Affine> a = skinningTransforms(model, body.joints, r);
    for (int k = 0; k < model.numJoints(); ++k)
      for (int e = 0; e < 12; ++e)
        s.transforms32(k, 12 * p + e) = float(a[size_t(k)](e / 4, e % 4));
  }
  s.features32 = s.features.cast<float>();
  return s;
}

// The joints whose features a vertex's refit may change, as a key ('1' for
// each used joint): those with a non-zero model weight and (options.parents)
// their parents; the root has no features, so a vertex of the root alone
// gets an empty key.
std::string jointsOf(const BodyModel& model, Eigen::Index i, bool parents) {
  std::string use(size_t(model.numJoints()), '0');
  for (int k = 0; k < model.numJoints(); ++k)
    if (model.weights(i, k) > 0) {
      use[size_t(k)] = '1';
      if (parents && model.parents[size_t(k)] >= 0) use[size_t(model.parents[size_t(k)])] = '1';
    }
  use[0] = '0';
  return use.find('1') == std::string::npos ? std::string() : use;
}

// The features of the joints of a jointsOf key: the 9 of each, in feature order.
std::vector<Eigen::Index> featuresOf(const std::string& joints) {
  std::vector<Eigen::Index> features;
  for (size_t k = 1; k < joints.size(); ++k)
    if (joints[k] == '1')
      for (int n = 0; n < 9; ++n) features.push_back(Eigen::Index(9 * (k - 1) + n));
  return features;
}

// A block of B vertices over one pose set: the pruning errors e_p (3B x T,
// vertex b at rows 3b..3b+2) and the rotation part R_p of the pruned skin's
// blend. e_p = (sum_k (w_k - u_k) A_k(p)) [x_p; 1]: the unpruned minus the
// pruned blend. Both blends are one product: the weight differences (rows
// 0..B-1) and the pruned weights (rows B..2B-1) times every A_k(p).
struct BlockPoses {
  Eigen::MatrixXd error;  // 3B x T
  Eigen::MatrixXf blend;  // 2B x 12T: row b's A(p) row by row at columns 12p + 4r + c
  Eigen::Matrix3d rotation(Eigen::Index b, Eigen::Index p) const {
    const Eigen::Index row = blend.rows() / 2 + b, ld = blend.rows();
    const float* a = &blend(row, 12 * p);
    Eigen::Matrix3d r;
    for (int e = 0; e < 12; ++e)
      if (e % 4 != 3) r(e / 4, e % 4) = double(a[e * ld]);
    return r;
  }
};

// What a block's products read of the model, gathered once for its pose
// sets: the posedirs rows (3B x P, in float), the weight differences and the
// pruned weights (2B x K, BlockPoses), v_shaped (B x 3).
struct BlockRows {
  Eigen::MatrixXf dirs, weights;
  Eigen::ArrayXXd rest;
};

BlockRows blockRows(const BodyModel& model, const ShapedBody& body, const SparseSkin& skin,
                    const std::vector<Eigen::Index>& ids) {
  const Eigen::Index b_count = Eigen::Index(ids.size());
  BlockRows out;
  out.dirs.resize(3 * b_count, model.numPoseFeatures());
  out.weights.resize(2 * b_count, model.numJoints());
  out.rest.resize(b_count, 3);
  Eigen::MatrixXd pruned = Eigen::MatrixXd::Zero(b_count, model.numJoints());
  for (Eigen::Index b = 0; b < b_count; ++b) {
    const Eigen::Index i = ids[size_t(b)];
    out.dirs.middleRows<3>(3 * b) = model.posedirs.middleRows<3>(3 * i).cast<float>();
    for (Eigen::Index s = 0; s < skin.joints.cols(); ++s)
      if (skin.weights(i, s) > 0) pruned(b, skin.joints(i, s)) += skin.weights(i, s);
    out.weights.row(b) = (model.weights.row(i) - pruned.row(b)).cast<float>();
    out.weights.row(b_count + b) = pruned.row(b).cast<float>();
    out.rest.row(b) = body.v_shaped.row(i);
  }
  return out;
}

BlockPoses blockPoses(const BlockRows& rows, const PoseSet& set) {
  const Eigen::Index b_count = rows.rest.rows(), t_count = set.features.cols();
  const Eigen::ArrayXXd& rest = rows.rest;
  // 3B x T: the posed rest vertices, less v_shaped
  const Eigen::MatrixXf x = fixedOrderProduct(rows.dirs, set.features32);
  BlockPoses out;
  fixedOrderProduct(rows.weights, set.transforms32, &out.blend);
  out.error.resize(3 * b_count, t_count);
  using Strided = Eigen::InnerStride<3>;  // coordinate c of every vertex: rows c, c + 3, ...
  std::array<Eigen::ArrayXd, 3> xp;
  // Pose by pose, all the block's vertices at once: a column of the blend
  // holds one entry of A(p) for every vertex. Each value is the sum
  // ((d0 x + d1 y) + d2 z) + d3 in double, as written out per vertex.
  for (Eigen::Index p = 0; p < t_count; ++p) {
    for (int c = 0; c < 3; ++c)
      xp[size_t(c)] =
          rest.col(c) +
          Eigen::Map<const Eigen::ArrayXf, 0, Strided>(&x(c, p), b_count).cast<double>();
    for (int r = 0; r < 3; ++r) {
      const auto d = [&](int k) {
        return Eigen::Map<const Eigen::ArrayXf>(&out.blend(0, 12 * p + 4 * r + k), b_count)
            .cast<double>();
      };
      Eigen::Map<Eigen::ArrayXd, 0, Strided>(&out.error(r, p), b_count) =
          d(0) * xp[0] + d(1) * xp[1] + d(2) * xp[2] + d(3);
    }
  }
  return out;
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

// Vertices with one feature set S, fitted together: D_i (3 x |S|) of each,
// or an empty matrix where the guard keeps the model's deltas.
// What every vertex with the feature set S shares: the ridge regression's
// map from a vertex's training targets to its D, W = F_S' (F_S F_S' +
// lambda I)^{-1} (T x |S|; so D_i = Z_i W for Z_i, 3 x T: one product per
// block instead of a product and a solve), and F_S of the validation poses.
struct FeatureSet {
  std::vector<Eigen::Index> features;  // S
  Eigen::MatrixXf solve;               // T x |S|: W, in float (PoseSet)
  Eigen::MatrixXf validate;            // |S| x Tv
};

FeatureSet featureSet(const Context& c, std::vector<Eigen::Index> s) {
  const Eigen::Index n = Eigen::Index(s.size());
  Eigen::MatrixXd h(n, n);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index col = 0; col < n; ++col) h(a, col) = c.gram(s[size_t(a)], s[size_t(col)]);
  const double lambda = c.options.ridge * std::max(h.diagonal().mean(), 1e-12);
  h.diagonal().array() += lambda;
  FeatureSet f;
  // W' = (F_S F_S' + lambda I)^{-1} F_S, the Gram matrix symmetric.
  f.solve = h.ldlt().solve(selectRows(c.train.features, s)).transpose().cast<float>();
  f.validate = selectRows(c.validate.features, s).cast<float>();
  f.features = std::move(s);
  return f;
}

struct Block {
  size_t set = 0;                      // its FeatureSet
  std::vector<Eigen::Index> vertices;  // at most kBlock
  std::vector<size_t> slots;           // where each vertex's D goes
};

// Guard: keep the model's deltas (false) if the refit raises the exact error
// |e_p - R_p D f_S(p)| of vertex b over the validation poses in the mean or at the maximum.
bool passesGuard(const BlockPoses& v, const Eigen::MatrixXf& correction, Eigen::Index b) {
  double before_sum = 0, before_max = 0, after_sum = 0, after_max = 0;
  for (Eigen::Index p = 0; p < v.error.cols(); ++p) {
    const Eigen::Vector3d e = v.error.block<3, 1>(3 * b, p);
    const double before = e.norm();
    const double after =
        (e - v.rotation(b, p) * correction.block<3, 1>(3 * b, p).cast<double>()).norm();
    before_sum += before, after_sum += after;
    before_max = std::max(before_max, before), after_max = std::max(after_max, after);
  }
  return after_sum <= before_sum && after_max <= before_max;
}

// The ridge regression of every vertex of the block (header), on its feature
// set's factored Gram matrix.
void fitBlock(const Context& c, const FeatureSet& set, const Block& block,
              std::vector<Eigen::MatrixXd>* deltas) {
  const BlockRows rows = blockRows(c.model, c.body, c.skin, block.vertices);
  const BlockPoses v = blockPoses(rows, c.train);
  const Eigen::Index b_count = Eigen::Index(block.vertices.size()), t_count = v.error.cols();
  Eigen::MatrixXf z(3 * b_count, t_count);  // rest-frame targets R_p^{-1} e_p
  for (Eigen::Index p = 0; p < t_count; ++p)
    for (Eigen::Index b = 0; b < b_count; ++b)
      z.block<3, 1>(3 * b, p) =
          (v.rotation(b, p).inverse() * v.error.block<3, 1>(3 * b, p)).cast<float>();
  const Eigen::MatrixXf d = fixedOrderProduct(z, set.solve);  // 3B x |S|: D_i at rows 3b..3b+2
  Eigen::MatrixXf correction;
  BlockPoses check;
  if (c.options.guard) {
    check = blockPoses(rows, c.validate);
    correction = fixedOrderProduct(d, set.validate);  // 3B x Tv: D_i f_S(p)
  }
  for (Eigen::Index b = 0; b < b_count; ++b)
    if (!c.options.guard || passesGuard(check, correction, b))
      (*deltas)[block.slots[size_t(b)]] = d.middleRows<3>(3 * b).cast<double>();
}

// The cut vertices grouped by feature set (each set prepared once, in
// `sets`, on `threads` workers: the sets are independent), in blocks of at
// most kBlock (in vertex order within a set, so the blocks do not depend on
// the thread count). (*set_of)[j]: the set of cut vertex j, or -1 (root only:
// nothing to refit).
std::vector<Block> blocksOf(const Context& c, const std::vector<Eigen::Index>& cut,
                            std::vector<int>* set_of, std::vector<FeatureSet>* sets) {
  std::map<std::string, std::vector<size_t>> groups;
  for (size_t j = 0; j < cut.size(); ++j) {
    std::string joints = jointsOf(c.model, cut[j], c.options.parents);
    if (!joints.empty()) groups[std::move(joints)].push_back(j);
  }
  std::vector<const std::string*> keys;
  for (const auto& group : groups) keys.push_back(&group.first);
  sets->resize(keys.size());
  std::atomic<size_t> next{0};
  runWorkers(std::max(1, std::min<int>(c.options.threads, int(keys.size()))), [&](int, int) {
    for (size_t g; (g = next++) < keys.size();) (*sets)[g] = featureSet(c, featuresOf(*keys[g]));
  });
  set_of->assign(cut.size(), -1);
  std::vector<Block> blocks;
  size_t g = 0;
  for (auto it = groups.begin(); it != groups.end(); ++it, ++g) {
    const std::vector<size_t>& members = it->second;
    for (size_t j : members) (*set_of)[j] = int(g);
    for (size_t first = 0; first < members.size(); first += size_t(kBlock)) {
      Block b;
      b.set = g;
      for (size_t j = first; j < std::min(members.size(), first + size_t(kBlock)); ++j) {
        b.vertices.push_back(cut[members[j]]);
        b.slots.push_back(members[j]);
      }
      blocks.push_back(std::move(b));
    }
  }
  return blocks;
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
  c.gram = fixedOrderProduct(c.train.features, c.train.features.transpose());
  std::vector<int> set_of;
  std::vector<FeatureSet> sets;
  const std::vector<Block> work = blocksOf(c, cut, &set_of, &sets);
  std::vector<Eigen::MatrixXd> deltas(cut.size());
  const int workers = std::max(1, std::min<int>(o.threads, int(work.size())));
  std::atomic<size_t> next{0};  // blocks are independent: any order gives the same result
  runWorkers(workers, [&](int, int) {
    for (size_t j; (j = next++) < work.size();) fitBlock(c, sets[work[j].set], work[j], &deltas);
  });
  refit.block.assign(size_t(n), -1);
  int blocks = 0;
  for (const Eigen::MatrixXd& d : deltas) blocks += d.size() > 0 ? 1 : 0;
  refit.kept = refit.cut - blocks;
  refit.rows.resize(3 * blocks, model.numPoseFeatures());
  int b = 0;
  for (size_t j = 0; j < cut.size(); ++j) {
    if (deltas[j].size() == 0) continue;
    refit.block[size_t(cut[j])] = b;
    const std::vector<Eigen::Index>& features = sets[size_t(set_of[j])].features;
    refit.rows.middleRows<3>(3 * b) = model.posedirs.middleRows<3>(3 * cut[j]);
    for (size_t f = 0; f < features.size(); ++f)
      refit.rows.block<3, 1>(3 * b, features[f]) += deltas[j].col(Eigen::Index(f));
    ++b;
  }
  if (blocks == 0) refit.block.clear();
  return refit;
}

void addRefitCorrection(const BodyModel& model, const ShapedBody& body, const SparseSkin& skin,
                        const CorrectiveRefit& refit, const std::vector<Rotations>& frames,
                        Eigen::MatrixXd* posed) {
  if (refit.empty()) return;
  std::vector<Eigen::Index> vertices;  // refitted vertex of each block, in block order
  vertices.resize(size_t(refit.rows.rows() / 3));
  for (size_t i = 0; i < refit.block.size(); ++i)
    if (refit.block[i] >= 0) vertices[size_t(refit.block[i])] = Eigen::Index(i);
  constexpr size_t kFrames = 64;       // frames per product
  constexpr Eigen::Index kRows = 384;  // rows of Q - P per product (128 vertices): cache-sized,
                                       // instead of a copy of the whole 3R x P difference
  for (size_t first = 0; first < frames.size(); first += kFrames) {
    const size_t count = std::min(kFrames, frames.size() - first);
    Eigen::MatrixXd features(model.numPoseFeatures(), Eigen::Index(count));
    std::vector<std::vector<Affine>> transforms(count);
    for (size_t t = 0; t < count; ++t) {
      features.col(Eigen::Index(t)) = poseFeatures(frames[first + t]);
      transforms[t] = skinningTransforms(model, body.joints, frames[first + t]);
    }
    Eigen::MatrixXd change, moved;
    for (Eigen::Index r0 = 0; r0 < refit.rows.rows(); r0 += kRows) {
      const Eigen::Index rows = std::min(kRows, refit.rows.rows() - r0);
      change = refit.rows.middleRows(r0, rows);  // Q_i - P_i of these vertices
      for (Eigen::Index b = 0; b < rows / 3; ++b)
        change.middleRows<3>(3 * b) -=
            model.posedirs.middleRows<3>(3 * vertices[size_t(r0 / 3 + b)]);
      fixedOrderProduct(change, features, &moved);  // rows x count
      for (Eigen::Index b = 0; b < rows / 3; ++b) {
        const Eigen::Index v = vertices[size_t(r0 / 3 + b)];
        for (size_t t = 0; t < count; ++t) {
          Eigen::Matrix3d r = Eigen::Matrix3d::Zero();  // the pruned skin's blended rotation
          for (Eigen::Index s = 0; s < skin.joints.cols(); ++s)
            if (skin.weights(v, s) > 0)
              r += skin.weights(v, s) * transforms[t][size_t(skin.joints(v, s))].leftCols<3>();
          posed->block<3, 1>(3 * v, Eigen::Index(first + t)) +=
              r * moved.block<3, 1>(3 * b, Eigen::Index(t));
        }
      }
    }
  }
}

}  // namespace smpl
