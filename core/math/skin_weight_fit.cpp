#include "core/math/skin_weight_fit.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <thread>
#include <vector>

#include "core/math/fixed_order_gemm.h"
#include "core/math/motion_poses.h"
#include "core/math/pose_sampler.h"
#include "core/math/skinning_transforms.h"
#include "core/parallel.h"

namespace smpl {
namespace {

// Joints a vertex's support is chosen from: its largest non-zero weights
// (at least 12, at least 2M).
constexpr int kMaxCandidates = 12;

struct TrainingSet {
  std::vector<std::vector<Affine>> transforms;  // [pose][joint]
  Eigen::MatrixXd v_posed;                      // 3N x T, column p = v_shaped + P f(p)
};

TrainingSet trainingSet(const BodyModel& model, const ShapedBody& body, const SkinFitOptions& o) {
  const std::vector<Eigen::VectorXd> poses =
      o.motion_like ? sampleMotionPoses(model.joint_names, o.training_poses, o.seed)
                    : samplePoses(model.numJoints(), o.training_poses, o.seed, o.pose_scale);
  TrainingSet ts;
  Eigen::MatrixXd features(model.numPoseFeatures(), static_cast<Eigen::Index>(poses.size()));
  for (size_t p = 0; p < poses.size(); ++p) {
    const Rotations r = rotationsFromAxisAngle(poses[p]);
    features.col(static_cast<Eigen::Index>(p)) = poseFeatures(r);
    ts.transforms.push_back(skinningTransforms(model, body.joints, r));
  }
  // One (3N x P)(P x T) product, summed in a fixed order: the same bits on
  // every CPU, and on any split of its rows over the workers.
  const Eigen::Index n = body.v_shaped.rows();
  ts.v_posed.resize(3 * n, features.cols());
  runWorkers(std::max(1, std::min<int>(o.threads, int(n / 256) + 1)), [&](int w, int count) {
    const Eigen::Index first = n * w / count, rows = 3 * (n * (w + 1) / count - first);
    Eigen::MatrixXd part;
    fixedOrderProduct(model.posedirs.middleRows(3 * first, rows), features, &part);
    Eigen::VectorXd rest(rows);  // v_shaped of these vertices, x y z per vertex
    for (Eigen::Index r = 0; r < rows; ++r) rest(r) = body.v_shaped(first + r / 3, r % 3);
    for (Eigen::Index p = 0; p < part.cols(); ++p)
      ts.v_posed.col(p).segment(3 * first, rows) = part.col(p) + rest;
  });
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

// Residuals of the candidate joints alone, stacked over the poses (3T x C):
// rows 3p..3p+2 of column s are d_ps = a_ps - y_p. With sum u = 1 the
// residual of weights u at pose p is sum_s u_s d_ps, and the training error
// is u' (D'D) u. The candidates are the first `c` of `nonzero`, so each
// a_k x of a pose is computed once, for y and for d.
Eigen::MatrixXd candidateResiduals(const BodyModel& model, const TrainingSet& ts, Eigen::Index i,
                                   const std::vector<int>& nonzero, size_t c) {
  const Eigen::Index poses = Eigen::Index(ts.transforms.size());
  Eigen::MatrixXd d(3 * poses, Eigen::Index(c));
  std::vector<Eigen::Vector3d> moved(nonzero.size());  // a_k x, k in `nonzero` order
  for (Eigen::Index p = 0; p < poses; ++p) {
    const std::vector<Affine>& a = ts.transforms[size_t(p)];
    const Eigen::Vector4d x = ts.v_posed.col(p).segment<3>(3 * i).homogeneous();
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (size_t j = 0; j < nonzero.size(); ++j) {
      moved[j] = a[size_t(nonzero[j])] * x;
      y += model.weights(i, nonzero[j]) * moved[j];
    }
    for (size_t s = 0; s < c; ++s) d.block<3, 1>(3 * p, Eigen::Index(s)) = moved[s] - y;
  }
  return d;
}

// d'd (C x C) of a residual matrix (3T x C): each entry one dot product of
// two columns, summed in row order (symmetric: the upper half is mirrored).
// Eigen's general product would pack the tiny operands first.
Eigen::MatrixXd gramOf(const Eigen::MatrixXd& d) {
  const Eigen::Index c = d.cols(), rows = d.rows();
  Eigen::MatrixXd g(c, c);
  for (Eigen::Index a = 0; a < c; ++a)
    for (Eigen::Index b = a; b < c; ++b) {
      const double* x = d.col(a).data();
      const double* y = d.col(b).data();
      double sum = 0.0;
      for (Eigen::Index r = 0; r < rows; ++r) sum += x[r] * y[r];
      g(a, b) = g(b, a) = sum;
    }
  return g;
}

// |sum_s u_s d_ps| per pose p (length T) for weights u on the candidate subset.
Eigen::VectorXd poseErrors(const Eigen::MatrixXd& d, const std::vector<int>& subset,
                           const Eigen::VectorXd& u) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(d.rows());
  for (size_t a = 0; a < subset.size(); ++a) r += u(Eigen::Index(a)) * d.col(subset[a]);
  Eigen::VectorXd e(d.rows() / 3);
  for (Eigen::Index p = 0; p < e.size(); ++p) e(p) = r.segment<3>(3 * p).norm();
  return e;
}

// Per-joint integers of a QP (flags, index lists) sized like Matrix: on the
// stack where Matrix is (SmallMatrix), so no step of the solver allocates.
template <class Matrix>
using Flags = Eigen::Matrix<int, Eigen::Dynamic, 1, 0, Matrix::MaxRowsAtCompileTime, 1>;

// Solves a x = b for the columns of `x` (b on entry) by the Cholesky factor
// a = L L' (a symmetric; L built in place of its lower half, row by row:
// Golub and Van Loan, Matrix Computations, algorithm 4.2.1), then forward
// and back substitution. False, with `x` unspecified, when a is not
// positive definite. Plain loops: the systems here are at most a few
// joints wide, where a general solver's setup costs more than the work.
template <class Matrix>
bool choleskySolve(Matrix a, Matrix* x) {
  const Eigen::Index f = a.rows();
  for (Eigen::Index j = 0; j < f; ++j) {
    double diagonal = a(j, j);
    for (Eigen::Index k = 0; k < j; ++k) diagonal -= a(j, k) * a(j, k);
    if (!(diagonal > 0.0)) return false;
    const double l = std::sqrt(diagonal);
    a(j, j) = l;
    for (Eigen::Index i = j + 1; i < f; ++i) {
      double v = a(i, j);
      for (Eigen::Index k = 0; k < j; ++k) v -= a(i, k) * a(j, k);
      a(i, j) = v / l;
    }
  }
  for (Eigen::Index c = 0; c < x->cols(); ++c) {
    for (Eigen::Index i = 0; i < f; ++i) {  // L y = b
      double v = (*x)(i, c);
      for (Eigen::Index k = 0; k < i; ++k) v -= a(i, k) * (*x)(k, c);
      (*x)(i, c) = v / a(i, i);
    }
    for (Eigen::Index i = f - 1; i >= 0; --i) {  // L' x = y
      double v = (*x)(i, c);
      for (Eigen::Index k = i + 1; k < f; ++k) v -= a(k, i) * (*x)(k, c);
      (*x)(i, c) = v / a(i, i);
    }
  }
  return true;
}

// Minimiser of 1/2 u'Hu - c'u with u_j = 0 for the active j and sum u = 1:
// the KKT system [H_FF -1; 1' 0][u_F; mu] = [c_F; 1], solved by its Schur
// complement: u_F = y + mu z with y = H_FF^{-1} c_F, z = H_FF^{-1} 1 and
// mu = (1 - 1'y) / 1'z, on one Cholesky factor of H_FF (positive definite:
// solveSimplexQp's precondition; a fourth of the cost of a pivoted LU of the
// bordered system). Returns u and mu. Matrix/Vector: SmallMatrix/SmallVector
// (at most kStackRows joints) or the dynamic types.
template <class Matrix, class Vector>
Vector equalityStep(const Matrix& h, const Vector& c, const Flags<Matrix>& active, double* mu) {
  Flags<Matrix> free_idx(active.size());  // the free joints' indices, in order
  int f = 0;
  for (int j = 0; j < int(active.size()); ++j)
    if (!active(j)) free_idx(f++) = j;
  Matrix hff(f, f);
  Matrix rhs(f, 2);
  for (int a = 0; a < f; ++a) {
    for (int b = 0; b < f; ++b) hff(a, b) = h(free_idx(a), free_idx(b));
    rhs(a, 0) = c(free_idx(a));
    rhs(a, 1) = 1.0;
  }
  Matrix yz = rhs;
  // Not positive definite (outside the precondition): the pivoted LU still solves it.
  if (!choleskySolve(hff, &yz)) yz = hff.fullPivLu().solve(rhs);
  *mu = (1.0 - yz.col(0).sum()) / yz.col(1).sum();
  Vector u = Vector::Zero(h.rows());
  for (int a = 0; a < f; ++a) u(free_idx(a)) = yz(a, 0) + *mu * yz(a, 1);
  return u;
}

// solveSimplexQp (skin_weight_fit.h) on Matrix/Vector (equalityStep).
template <class Matrix, class Vector>
Vector simplexQp(const Matrix& h, const Vector& c, const Vector& u0) {
  const int m = int(h.rows());
  Vector u = u0;
  Flags<Matrix> active(m);
  for (int j = 0; j < m; ++j) active(j) = u(j) <= 0.0;
  const double tol = 1e-12 * std::max(1e-300, h.diagonal().cwiseAbs().maxCoeff());
  for (int iter = 0; iter < 10 * m + 10; ++iter) {
    double mu = 0.0;
    const Vector target = equalityStep<Matrix, Vector>(h, c, active, &mu);
    double alpha = 1.0;
    int blocking = -1;
    for (int j = 0; j < m; ++j)  // longest feasible step towards target
      if (!active(j) && target(j) < 0.0) {
        const double ratio = u(j) / (u(j) - target(j));
        if (ratio < alpha) alpha = ratio, blocking = j;
      }
    u += alpha * (target - u);
    if (blocking >= 0) {
      active(blocking) = 1;
      u(blocking) = 0.0;
      continue;
    }
    const Vector g = h * u - c;  // multiplier of u_j >= 0 is g_j - mu
    int release = -1;
    double worst = -tol;
    for (int j = 0; j < m; ++j)
      if (active(j) && g(j) - mu < worst) worst = g(j) - mu, release = j;
    if (release < 0) break;  // KKT conditions hold: optimal
    active(release) = 0;
  }
  u = u.cwiseMax(0.0);
  return u / u.sum();
}

// One vertex's fitting problem: candidate residuals, their Gram matrix and
// the model's weights of the candidates.
struct VertexFit {
  Eigen::MatrixXd d;      // 3T x C, candidateResiduals
  Eigen::MatrixXd gram;   // C x C, d'd
  Eigen::VectorXd model;  // C, the model's weights of the candidates
  double lambda = 0.1;    // SkinFitOptions::prior_strength
};

// Matrices of at most kStackRows rows and columns live on the stack: the
// fit solves hundreds of thousands of tiny systems per body, and heap
// allocation was a sixth of its time. Larger ones (M > 16) use the heap.
constexpr int kStackRows = 16;
using SmallMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kStackRows, kStackRows>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kStackRows, 1>;

template <class Matrix, class Vector>
double fitSubsetOn(const VertexFit& v, const Eigen::MatrixXd& gram, const std::vector<int>& subset,
                   Eigen::VectorXd* u) {
  const int m = int(subset.size());
  Matrix d(m, m);
  Vector prior(m);
  for (int a = 0; a < m; ++a) {
    prior(a) = v.model(subset[size_t(a)]);
    for (int b = 0; b < m; ++b) d(a, b) = gram(subset[size_t(a)], subset[size_t(b)]);
  }
  prior /= prior.sum();
  // 1e-6: keeps the system regular when two joints move a vertex alike.
  const double ridge = (v.lambda + 1e-6) * d.trace() / m + 1e-300;
  Matrix h = d;
  h.diagonal().array() += ridge;
  h *= 2.0;
  const Vector c = 2.0 * ridge * prior;
  const Vector w = simplexQp<Matrix, Vector>(h, c, prior);
  *u = w;
  return w.dot(d * w);
}

// Fitted weights on the candidate subset `subset` (indices into the
// candidates) from the Gram matrix `gram`, and their training error u'Du.
// Prior (the ridge's anchor and the solver's feasible start): the model's
// weights of the subset, renormalised.
double fitSubset(const VertexFit& v, const Eigen::MatrixXd& gram, const std::vector<int>& subset,
                 Eigen::VectorXd* u) {
  if (subset.size() == 1) {  // the simplex is one point
    *u = Eigen::VectorXd::Ones(1);
    return gram(subset[0], subset[0]);
  }
  return int(subset.size()) <= kStackRows
             ? fitSubsetOn<SmallMatrix, SmallVector>(v, gram, subset, u)
             : fitSubsetOn<Eigen::MatrixXd, Eigen::VectorXd>(v, gram, subset, u);
}

// Number of m-subsets of c things (as a double: no overflow).
double subsets(int c, int m) {
  double n = 1.0;
  for (int a = 0; a < m; ++a) n = n * (c - a) / (a + 1);
  return n;
}

// Lowest-training-error support of size m among the candidates (see the
// header's support rule), starting from the M largest (`*best` on entry).
void searchSupport(const VertexFit& v, int m, int exhaustive_limit, std::vector<int>* best,
                   Eigen::VectorXd* best_u) {
  const int c = int(v.model.size());
  double best_err = fitSubset(v, v.gram, *best, best_u);
  Eigen::VectorXd u;
  auto consider = [&](const std::vector<int>& subset) {
    const double err = fitSubset(v, v.gram, subset, &u);
    if (err < best_err) best_err = err, *best = subset, *best_u = u;
  };
  if (subsets(c, m) <= exhaustive_limit) {
    std::vector<int> subset(static_cast<size_t>(m));
    std::iota(subset.begin(), subset.end(), 0);
    for (;;) {  // every m-subset in lexicographic order
      consider(subset);
      int a = m - 1;
      while (a >= 0 && subset[size_t(a)] == c - m + a) --a;
      if (a < 0) return;
      ++subset[size_t(a)];
      for (int b = a + 1; b < m; ++b) subset[size_t(b)] = subset[size_t(b - 1)] + 1;
    }
  }
  std::vector<int> greedy, trial;  // forward selection; ties: the larger model weight
  greedy.reserve(size_t(m)), trial.reserve(size_t(m));
  for (int step = 0; step < m; ++step) {
    int pick = -1;
    double pick_err = 0.0;
    for (int s = 0; s < c; ++s) {
      if (std::find(greedy.begin(), greedy.end(), s) != greedy.end()) continue;
      trial.assign(greedy.begin(), greedy.end());  // reuses its storage
      trial.push_back(s);
      const double err = fitSubset(v, v.gram, trial, &u);
      if (pick < 0 || err < pick_err) pick = s, pick_err = err;
    }
    greedy.push_back(pick);
  }
  consider(greedy);
}

// Iteratively reweighted least squares toward the smallest sum of per-pose
// distances on a fixed support (each step minimises sum_p e_p^2 / e'_p with
// e' the previous step's distances, floor 1e-3 of their mean: a
// majorise-minimise step that cannot increase the sum, as in Weiszfeld's
// algorithm for the geometric median).
void refineL1(const VertexFit& v, const std::vector<int>& subset, int iterations,
              Eigen::VectorXd* u) {
  for (int it = 0; it < iterations; ++it) {
    const Eigen::VectorXd e = poseErrors(v.d, subset, *u);
    const double floor = 1e-3 * e.mean() + 1e-300;
    Eigen::MatrixXd dw = v.d;
    for (Eigen::Index p = 0; p < e.size(); ++p)
      dw.middleRows<3>(3 * p) /= std::sqrt(std::max(e(p), floor));
    fitSubset(v, dw.transpose() * dw, subset, u);
  }
}

// The fitted row of vertex i (see the header: support rule, prior, guard).
void fitVertex(const BodyModel& model, const TrainingSet& ts, const SkinFitOptions& o,
               Eigen::Index i, int m, SparseSkin* skin) {
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
  VertexFit v;
  v.d = candidateResiduals(model, ts, i, nonzero, candidates.size());
  v.gram = gramOf(v.d);
  v.model.resize(Eigen::Index(candidates.size()));
  for (size_t s = 0; s < candidates.size(); ++s)
    v.model(Eigen::Index(s)) = model.weights(i, candidates[s]);
  v.lambda = o.prior_strength;
  std::vector<int> top(static_cast<size_t>(m)), best;
  std::iota(top.begin(), top.end(), 0);
  best = top;
  Eigen::VectorXd u;
  searchSupport(v, m, o.exhaustive_limit, &best, &u);
  refineL1(v, best, o.l1_iterations, &u);
  std::vector<int> joints;
  for (int s : best) joints.push_back(candidates[size_t(s)]);
  const Eigen::VectorXd truncated = v.model.head(m) / v.model.head(m).sum();
  if (o.guard && poseErrors(v.d, best, u).maxCoeff() > poseErrors(v.d, top, truncated).maxCoeff())
    return storeRow(i, std::vector<int>(candidates.begin(), candidates.begin() + m), truncated,
                    skin);
  storeRow(i, joints, u, skin);
}

}  // namespace

Eigen::VectorXd solveSimplexQp(const Eigen::MatrixXd& h, const Eigen::VectorXd& c,
                               const Eigen::VectorXd& u0) {
  return simplexQp<Eigen::MatrixXd, Eigen::VectorXd>(h, c, u0);
}

SparseSkin fitSkinWeights(const BodyModel& model, const ShapedBody& body, const SkinFitOptions& o) {
  const Eigen::Index n = model.numVertices();
  const int m = std::max(1, std::min(o.max_influences, model.numJoints()));
  SparseSkin skin;
  skin.joints = Eigen::MatrixXi::Zero(n, m);
  skin.weights = Eigen::MatrixXd::Zero(n, m);
  const TrainingSet ts = trainingSet(model, body, o);
  const int workers = std::max(1, std::min<int>(o.threads, int(n / 256) + 1));
  runWorkers(workers, [&](int w, int count) {
    for (Eigen::Index i = w; i < n; i += count) fitVertex(model, ts, o, i, m, &skin);
  });
  return skin;
}

}  // namespace smpl
