// Animated SMPL-X expressions (a motion's per-frame `expression` coefficients,
// e.g. BEAT2 `expressions` (T,100), Motion-X, SMPLCodec `expressionParameters`)
// baked as weights of the expr_<i> morph targets (--expression-keys N).
//
// Encoding: the coefficients are unbounded, so, as DMPL's (dmpl_targets.h),
// each baked target gets weight = scale * c + offset in [0, 1] over the
// motions' range of c = psi_i(t) - psi_i_rest (psi_rest = the static
// --expression already in the base mesh); its deltas are E_i / scale, its rest
// weight the offset, and the base mesh is shifted by -sum (offset/scale) E_i,
// so the rest pose stays v_shaped(betas, psi_rest) and every frame gives
// v_shaped(betas, psi(t)) exactly in the expr_ part.
//
// Joints: the authors' SMPL-X (vchoutas/smplx body_models.py SMPLX.forward:
// shape_components = [betas, expression]; J = J_regressor v_shaped) regress
// the joints from the expression too. The export keeps the rest shape's
// skeleton (as --dmpl-joints fixed does); the vertex error this costs is
// measured every frame (AnimationClip::expression_joint_error, joint_shift_cost.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/motions/motion.h"
#include "exporter/asset.h"

namespace smpl {

// Layout of the first `count` expression coefficients over `coefficients`
// (T x E each, columns beyond E read as psi_rest), relative to `rest`.
std::vector<ExpressionLayout> expressionLayout(
    int count, const std::vector<double>& rest,
    const std::vector<const Eigen::MatrixXd*>& coefficients);

// Re-encodes the expr_<i> targets already in the mesh (pipeline.h adds them
// with weight = coefficient) per `layout`, shifts the base mesh, and fills
// asset->metadata.expression_targets (with the joints' directions).
void encodeExpressionTargets(const BodyModel& model, const std::vector<ExpressionLayout>& layout,
                             Asset* asset);

// The coefficients at source position frame + t (linear), `count` of them
// (those the motion lacks read as `rest`).
Eigen::VectorXd expressionAt(const Motion& motion, int frame, double t, int count,
                             const std::vector<double>& rest);

// One output frame: the expr_ weights and the fixed-joint cost. `local` = the
// frame's local rotations as exported (root including `up`).
void applyExpressionFrame(const Asset& asset, const Eigen::VectorXd& psi, const Rotations& local,
                          const Eigen::Matrix3d& up, int frame, AnimationClip* clip);

// What the user must know about a motion's expression (one line each, none
// when it has none): not baked (no --expression-keys), coefficients dropped
// (fewer keys than the motion has, or than the model has directions: the
// largest dropped |value|), and after baking the fixed-joint cost.
std::vector<std::string> expressionNotes(const Motion& motion, int exported, int model_count);

}  // namespace smpl
