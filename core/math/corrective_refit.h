// Pose correctives refitted to a pruned skin. Cutting a vertex's skin to M
// influences (pruneWeights or fitSkinWeights) moves it away from the
// unpruned model at most poses, and weights alone cannot undo it (measured:
// the best weights on the kept joints reach 13% below truncation). The
// correctives can: they are linear in the pose features f, and the pruning
// error is mostly a function of the rotations of the joints that move the
// vertex. So for every vertex whose influences were cut, new corrective rows
// Q_i = P_i + D_i (3 x P) are fitted so that the pruned skin u reproduces the
// model with all its weights w over training poses p:
//
//   x_p = v_shaped_i + P_i f(p)                   (the model's posed rest vertex)
//   y_p = sum_k w_ik A_k(p) [x_p; 1]              (the unpruned model)
//   B_p = sum_s u_s A_{k_s}(p) = [R_p | t_p]      (the pruned skin's blend)
//   e_p = y_p - B_p [x_p; 1]                      (the pruning error)
//   minimise  sum_p |R_p^{-1} e_p - D_i f_S(p)|^2 + lambda |D_i|^2
//
// with D_i non-zero only on the features S of the joints that move the
// vertex (non-zero model weights) and their parents (the variant that held
// on real motion in our experiment). The residual is taken in the
// rest frame (R_p^{-1} e_p): B_p (x_p + D_i f) = B_p x_p + R_p D_i f, and R_p is
// a blend of rotations, near orthonormal, so this is the least-squares
// problem up to R_p's conditioning, and it splits into three ridge
// regressions that share one Gram matrix (F_S F_S' + lambda I) per vertex.
// lambda = ridge x the mean diagonal of F_S F_S' (pulls D_i toward 0: the
// model's deltas). Guard: on validation poses (other seeds: motion-like and
// uniform random), a vertex keeps the model's deltas if the refit raises the
// exact error |e_p - R_p D_i f_S(p)| in the mean or at the maximum.
// Training and validation poses are motion-like (core/math/motion_poses.h):
// trained on uniform random poses the refit overfits them.
// Cost: the vertices with one feature set S share the Gram matrix and its
// factor; they are fitted in blocks of 32 whose posed vertices, blends and
// right-hand sides are matrix products (the dense 6890-vertex stand-in:
// 0.1 s on 2 cores with the fixed-order AVX-512 products in float and one
// product per block for the ridge solve, was 0.3 s on Eigen's double
// products, 2.2 s vertex by vertex).
// Deterministic: the result does not depend on the thread count.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/body_model.h"
#include "core/math/forward.h"
#include "core/math/skin_weights.h"

namespace smpl {

struct CorrectiveRefitOptions {
  int training_poses = 240;              // motion-like poses of the fit
  uint64_t seed = 0x7e417c0e5eedull;     // training set; not a report's seed
  int validation_poses = 32;             // guard: this many motion-like + as many uniform
  uint64_t validation_seed = 0x9a4dull;  // guard's poses; not a report's seed
  double validation_scale = 0.6;         // radians, the uniform validation poses
  double ridge = 1e-3;                   // lambda / mean diagonal of the features' Gram matrix
  bool parents = true;                   // features of the moving joints' parents too
  bool guard = true;                     // keep the model's deltas where the refit is worse
  int threads = 2;                       // worker threads over vertices
};

// The refitted rows of posedirs; every other row is the model's.
struct CorrectiveRefit {
  std::vector<int> block;  // N entries: vertex i's block in `rows`, -1 = the model's posedirs
  Eigen::MatrixXd rows;    // 3R x P: row 3 block(i) + c is posedirs row 3i + c, refitted
  int cut = 0;             // vertices whose influences were cut (the refit was tried)
  int kept = 0;            // of those, vertices the guard left with the model's deltas

  bool empty() const { return rows.rows() == 0; }
  // posedirs(3i + c, n) as exported: the refitted value where there is one.
  double delta(const BodyModel& model, Eigen::Index row, Eigen::Index feature) const;
  // Column n of posedirs as exported (3N).
  Eigen::VectorXd column(const BodyModel& model, Eigen::Index feature) const;
  // The whole 3N x P matrix as exported (for --corrective-basis).
  Eigen::MatrixXd posedirs(const BodyModel& model) const;
};

// Refit for the subject `body` (shapeBody of the exported betas) skinned
// with `skin` (N x M, pruneWeights layout). Vertices with no more non-zero
// model weights than the skin keeps are exact already and are not touched.
CorrectiveRefit refitCorrectives(const BodyModel& model, const ShapedBody& body,
                                 const SparseSkin& skin, const CorrectiveRefitOptions& options);

// Adds what the refit changes to posed vertices: for every refitted vertex i
// and frame t, R_t (Q_i - P_i) f(t) is added to rows 3i..3i+2 of column t of
// `posed` (3N x T, forwardBatch's layout, the frames skinned with `skin`).
void addRefitCorrection(const BodyModel& model, const ShapedBody& body, const SparseSkin& skin,
                        const CorrectiveRefit& refit, const std::vector<Rotations>& frames,
                        Eigen::MatrixXd* posed);

}  // namespace smpl
