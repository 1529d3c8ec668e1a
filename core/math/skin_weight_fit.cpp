#include "core/math/skin_weight_fit.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <numeric>
#include <thread>
#include <vector>

#include "core/math/pose_sampler.h"

namespace smpl {
namespace {

using Affine = Eigen::Matrix<double, 3, 4>;

// Joints a vertex's support is chosen from: its largest non-zero weights
// (at least 12, at least 2M).
constexpr int kMaxCandidates = 12;

// A_k = G_k [I | -J_k] of every joint for one pose (docs/file-contract.md).
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

struct TrainingSet {
  std::vector<std::vector<Affine>> transforms;  // [pose][joint]
  Eigen::MatrixXd v_posed;                      // 3N x T, column p = v_shaped + P f(p)
};

TrainingSet trainingSet(const BodyModel& model, const ShapedBody& body, const SkinFitOptions& o) {
  const std::vector<Eigen::VectorXd> poses =
      samplePoses(model.numJoints(), o.training_poses, o.seed, o.pose_scale);
  TrainingSet ts;
  Eigen::MatrixXd features(model.numPoseFeatures(), static_cast<Eigen::Index>(poses.size()));
  for (size_t p = 0; p < poses.size(); ++p) {
    const Rotations r = rotationsFromAxisAngle(poses[p]);
    features.col(static_cast<Eigen::Index>(p)) = poseFeatures(r);
    ts.transforms.push_back(skinningTransforms(model, body.joints, r));
  }
  ts.v_posed = model.posedirs * features;  // one (3N x P)(P x T) product
  for (Eigen::Index i = 0; i < body.v_shaped.rows(); ++i)
    for (int c = 0; c < 3; ++c) ts.v_posed.row(3 * i + c).array() += body.v_shaped(i, c);
  return ts;
}

// Joints of vertex i by descending model weight, ties to the lower index.
std::vector<int> jointsByWeight(const Eigen::MatrixXd& weights, Eigen::Index i) {
  std::vector<int> order(static_cast<size_t>(weights.cols()));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return weights(i, a) > weights(i, b); });
  return order;
}

// Writes joints/weights sorted by descending weight (ties: lower joint), zero
// weights as unused slots (joint 0, weight 0), renormalised to sum 1.
void storeRow(Eigen::Index i, const std::vector<int>& joints, Eigen::VectorXd u, SparseSkin* skin) {
  u = u.cwiseMax(0.0);
  u /= u.sum();
  std::vector<int> slot(joints.size());
  std::iota(slot.begin(), slot.end(), 0);
  std::stable_sort(slot.begin(), slot.end(), [&](int a, int b) {
    return u(a) != u(b) ? u(a) > u(b) : joints[size_t(a)] < joints[size_t(b)];
  });
  for (size_t s = 0; s < slot.size(); ++s) {
    const double w = u(slot[s]);
    skin->joints(i, Eigen::Index(s)) = w > 0 ? joints[size_t(slot[s])] : 0;
    skin->weights(i, Eigen::Index(s)) = w > 0 ? w : 0.0;
  }
}

// D_st = sum_p d_ps . d_pt over the candidate joints, d_ps = a_ps - y_p:
// with sum u = 1 the residual of weights u is sum_s u_s d_ps, so the fit
// error over the training poses is u' D u.
Eigen::MatrixXd residualGram(const BodyModel& model, const TrainingSet& ts, Eigen::Index i,
                             const std::vector<int>& nonzero, const std::vector<int>& candidates) {
  const int c = int(candidates.size());
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(c, c);
  Eigen::Matrix3Xd d(3, c);
  for (size_t p = 0; p < ts.transforms.size(); ++p) {
    const Eigen::Vector4d x = ts.v_posed.col(Eigen::Index(p)).segment<3>(3 * i).homogeneous();
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (int k : nonzero) y += model.weights(i, k) * (ts.transforms[p][size_t(k)] * x);
    for (int s = 0; s < c; ++s) d.col(s) = ts.transforms[p][size_t(candidates[size_t(s)])] * x - y;
    gram.noalias() += d.transpose() * d;
  }
  return gram;
}

// Largest |sum_s u_s a_ps - y_p| over the training poses.
double maxResidual(const BodyModel& model, const TrainingSet& ts, Eigen::Index i,
                   const std::vector<int>& nonzero, const std::vector<int>& joints,
                   const Eigen::VectorXd& u) {
  double worst = 0.0;
  for (size_t p = 0; p < ts.transforms.size(); ++p) {
    const Eigen::Vector4d x = ts.v_posed.col(Eigen::Index(p)).segment<3>(3 * i).homogeneous();
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (int k : nonzero) r -= model.weights(i, k) * (ts.transforms[p][size_t(k)] * x);
    for (size_t s = 0; s < joints.size(); ++s)
      r += u(Eigen::Index(s)) * (ts.transforms[p][size_t(joints[s])] * x);
    worst = std::max(worst, r.norm());
  }
  return worst;
}

// Fitted weights on the candidate subset `subset` (indices into the Gram
// matrix) and their training error u' D u. `prior` (same length) is the
// ridge's anchor and the solver's feasible start.
double fitSubset(const Eigen::MatrixXd& gram, const std::vector<int>& subset,
                 const Eigen::VectorXd& prior, Eigen::VectorXd* u) {
  const int m = int(subset.size());
  Eigen::MatrixXd d(m, m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) d(a, b) = gram(subset[size_t(a)], subset[size_t(b)]);
  const double ridge = 1e-6 * d.trace() / m + 1e-300;
  const Eigen::MatrixXd h = 2.0 * (d + ridge * Eigen::MatrixXd::Identity(m, m));
  *u = solveSimplexQp(h, 2.0 * ridge * prior, prior);
  return u->dot(d * *u);
}

// Support rule: the better (lower training error) of (a) the m largest
// weights and (b) greedy forward selection among the candidates (each step
// adds the joint that lowers the fitted error most; ties: larger weight).
// Guard: if the fit's largest training-pose error exceeds truncation's, the
// vertex keeps its truncated weights (so the worst case does not grow).
void fitVertex(const BodyModel& model, const TrainingSet& ts, Eigen::Index i, int m,
               SparseSkin* skin) {
  const std::vector<int> order = jointsByWeight(model.weights, i);
  int count = 0;
  while (count < int(order.size()) && model.weights(i, order[size_t(count)]) > 0) ++count;
  if (count == 0)
    return storeRow(i, {0}, Eigen::VectorXd::Ones(1), skin);  // no weight: follows the root
  const std::vector<int> nonzero(order.begin(), order.begin() + count);
  if (count <= m) {  // every influence kept: exact
    Eigen::VectorXd u(count);
    for (int s = 0; s < count; ++s) u(s) = model.weights(i, nonzero[size_t(s)]);
    return storeRow(i, nonzero, u / u.sum(), skin);
  }
  const std::vector<int> candidates(
      nonzero.begin(), nonzero.begin() + std::min(count, std::max(kMaxCandidates, 2 * m)));
  const Eigen::MatrixXd gram = residualGram(model, ts, i, nonzero, candidates);
  std::vector<int> top(static_cast<size_t>(m), 0);
  std::iota(top.begin(), top.end(), 0);
  Eigen::VectorXd prior(m), best_u;
  for (int s = 0; s < m; ++s) prior(s) = model.weights(i, candidates[size_t(s)]);
  double best = fitSubset(gram, top, prior / prior.sum(), &best_u);
  std::vector<int> best_set = top, greedy;
  for (int step = 0; step < m; ++step) {
    int pick = -1;
    double pick_err = 0.0;
    Eigen::VectorXd u;
    for (int c = 0; c < int(candidates.size()); ++c) {
      if (std::find(greedy.begin(), greedy.end(), c) != greedy.end()) continue;
      std::vector<int> trial = greedy;
      trial.push_back(c);
      const double err = fitSubset(
          gram, trial, Eigen::VectorXd::Constant(int(trial.size()), 1.0 / trial.size()), &u);
      if (pick < 0 || err < pick_err) pick = c, pick_err = err;
    }
    greedy.push_back(pick);
  }
  Eigen::VectorXd greedy_u;
  const double greedy_err =
      fitSubset(gram, greedy, Eigen::VectorXd::Constant(m, 1.0 / m), &greedy_u);
  if (greedy_err < best) best_set = greedy, best_u = greedy_u;
  std::vector<int> joints, top_joints(candidates.begin(), candidates.begin() + m);
  for (int s : best_set) joints.push_back(candidates[size_t(s)]);
  // Never worse at the vertex's worst training pose than truncation.
  const Eigen::VectorXd truncated = prior / prior.sum();
  if (maxResidual(model, ts, i, nonzero, joints, best_u) >
      maxResidual(model, ts, i, nonzero, top_joints, truncated))
    return storeRow(i, top_joints, truncated, skin);
  storeRow(i, joints, best_u, skin);
}

// Minimiser of 1/2 u'Hu - c'u with u_j = 0 for the active j and sum u = 1:
// the KKT system [H_FF -1; 1' 0][u_F; mu] = [c_F; 1]. Returns u and mu.
Eigen::VectorXd equalityStep(const Eigen::MatrixXd& h, const Eigen::VectorXd& c,
                             const std::vector<bool>& active, double* mu) {
  std::vector<int> free_idx;
  for (int j = 0; j < int(active.size()); ++j)
    if (!active[size_t(j)]) free_idx.push_back(j);
  const int f = int(free_idx.size());
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(f + 1, f + 1);
  Eigen::VectorXd rhs(f + 1);
  for (int a = 0; a < f; ++a) {
    for (int b = 0; b < f; ++b) kkt(a, b) = h(free_idx[size_t(a)], free_idx[size_t(b)]);
    kkt(a, f) = -1.0;
    kkt(f, a) = 1.0;
    rhs(a) = c(free_idx[size_t(a)]);
  }
  rhs(f) = 1.0;
  const Eigen::VectorXd sol = kkt.fullPivLu().solve(rhs);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(h.rows());
  for (int a = 0; a < f; ++a) u(free_idx[size_t(a)]) = sol(a);
  *mu = sol(f);
  return u;
}

}  // namespace

Eigen::VectorXd solveSimplexQp(const Eigen::MatrixXd& h, const Eigen::VectorXd& c,
                               const Eigen::VectorXd& u0) {
  const int m = int(h.rows());
  Eigen::VectorXd u = u0;
  std::vector<bool> active(static_cast<size_t>(m), false);
  for (int j = 0; j < m; ++j) active[size_t(j)] = u(j) <= 0.0;
  const double tol = 1e-12 * std::max(1e-300, h.diagonal().cwiseAbs().maxCoeff());
  for (int iter = 0; iter < 10 * m + 10; ++iter) {
    double mu = 0.0;
    const Eigen::VectorXd target = equalityStep(h, c, active, &mu);
    double alpha = 1.0;
    int blocking = -1;
    for (int j = 0; j < m; ++j)  // longest feasible step towards target
      if (!active[size_t(j)] && target(j) < 0.0) {
        const double ratio = u(j) / (u(j) - target(j));
        if (ratio < alpha) alpha = ratio, blocking = j;
      }
    u += alpha * (target - u);
    if (blocking >= 0) {
      active[size_t(blocking)] = true;
      u(blocking) = 0.0;
      continue;
    }
    const Eigen::VectorXd g = h * u - c;  // multiplier of u_j >= 0 is g_j - mu
    int release = -1;
    double worst = -tol;
    for (int j = 0; j < m; ++j)
      if (active[size_t(j)] && g(j) - mu < worst) worst = g(j) - mu, release = j;
    if (release < 0) break;  // KKT conditions hold: optimal
    active[size_t(release)] = false;
  }
  u = u.cwiseMax(0.0);
  return u / u.sum();
}

SparseSkin fitSkinWeights(const BodyModel& model, const ShapedBody& body, const SkinFitOptions& o) {
  const Eigen::Index n = model.numVertices();
  const int m = std::max(1, std::min(o.max_influences, model.numJoints()));
  SparseSkin skin;
  skin.joints = Eigen::MatrixXi::Zero(n, m);
  skin.weights = Eigen::MatrixXd::Zero(n, m);
  const TrainingSet ts = trainingSet(model, body, o);
  const int workers = std::max(1, std::min<int>(o.threads, int(n / 256) + 1));
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w)
    pool.emplace_back([&, w] {
      for (Eigen::Index i = w; i < n; i += workers) fitVertex(model, ts, i, m, &skin);
    });
  for (std::thread& t : pool) t.join();
  return skin;
}

}  // namespace smpl
