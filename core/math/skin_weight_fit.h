// Fitted skin weights: instead of keeping the M largest weights of a vertex
// and renormalising them (pruneWeights, the usual practice), choose M joints
// and non-negative weights summing to 1 that best reproduce the unpruned model
// over a set of training poses. Linear blend skinning is linear in the
// weights, so per vertex this is a small quadratic program:
//
//   a_ps = A_{k_s}(p) v_posed_i(p)          (3-vector: vertex i moved by joint k_s alone)
//   y_p  = sum_k w_ik A_k(p) v_posed_i(p)   (the model with all its weights)
//   minimise  sum_p |sum_s u_s a_ps - y_p|^2 + lambda |u - u_prior|^2
//   over u >= 0, sum_s u_s = 1,
//
// solved exactly by a primal active-set method (Nocedal & Wright, "Numerical
// Optimization", 2nd ed., algorithm 16.3). u_prior is the model's weights on
// the support, renormalised (on the M largest joints: the truncated weights);
// lambda = prior_strength x the mean diagonal of the support's Gram matrix.
// The pull toward the prior is shrinkage: it costs little training error
// and keeps the fit from trading rare large errors on poses it never saw for
// small ones on the poses it did (the held-out maximum). Support rule: the
// candidates are the vertex's largest non-zero weights (up to 12, or 2M
// if more); every M-subset of them when there are at most exhaustive_limit
// subsets, otherwise the better of the M largest and greedy forward
// selection (each step adds the joint that lowers the fitted error most);
// the subset of lowest training error wins. Guard: a vertex whose fit is
// worse than truncation at its worst training pose keeps the truncated
// weights. A vertex with at most M non-zero weights keeps its exact weights.
// Poses: motion-like poses (sampleMotionPoses, core/math/motion_poses.h:
// joint ranges and correlations of captured motion) with a seed of their
// own; trained on uniform random poses instead (motion_like = false), the
// fit overfitted them and was worse than truncation at the maximum on a real
// AMASS clip. Reports that measure the error on the report seeds
// (exporter/pruning_error.h) measure held-out poses.
// Deterministic: the result does not depend on the thread count.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "core/body_model.h"
#include "core/math/forward.h"
#include "core/math/skin_weights.h"

namespace smpl {

struct SkinFitOptions {
  int max_influences = 4;           // M, 1..K (a precondition: clamped to it, not checked)
  int training_poses = 48;          // poses of the fit
  uint64_t seed = 0x5157a11f17ull;  // training set; differs from the report's held-out seeds
  bool motion_like = true;          // sampleMotionPoses; false: uniform in +-pose_scale rad
  double pose_scale = 0.6;          // radians, as samplePoses (motion_like false only)
  int threads = 2;                  // worker threads over vertices (result is thread-independent)
  double prior_strength = 0.1;      // lambda / mean Gram diagonal: pull toward the prior weights
  int exhaustive_limit = 70;        // try every M-subset of the candidates up to this many subsets
  bool guard = true;                // keep truncation where the fit's worst training pose is worse
  // > 0: after the support is chosen, this many iteratively reweighted least
  // squares steps (weights 1 / |residual_p|) minimise sum_p |residual_p|, the
  // summed distance a mean-error report measures, instead of its square.
  int l1_iterations = 0;
};

// Fitted N x M skin of the subject `body` (shapeBody of the exported betas).
// Same layout as pruneWeights: joints sorted by descending fitted weight
// (ties: lower joint index), unused slots joint 0 with weight 0, rows sum to 1.
SparseSkin fitSkinWeights(const BodyModel& model, const ShapedBody& body,
                          const SkinFitOptions& options);

// The quadratic program of one vertex: minimise 1/2 u'Hu - c'u over
// u >= 0, sum u = 1 (H symmetric positive definite, m x m), from the feasible
// start `u0` (u0 >= 0, sum 1). Returns the minimiser (exact up to rounding).
Eigen::VectorXd solveSimplexQp(const Eigen::MatrixXd& h, const Eigen::VectorXd& c,
                               const Eigen::VectorXd& u0);

}  // namespace smpl
