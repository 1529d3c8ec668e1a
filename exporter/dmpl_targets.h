// DMPL soft-tissue dynamics as morph targets (core/models/dmpl.h): one target
// `dmpl_<i>` per basis direction, deltas in the rest pose (model axes), and
// per-frame weights from the motion's `dmpls`. The coefficients are unbounded,
// so each target gets an affine encoding from the motions' range,
// weight = scale * c + offset in [0, 1] (importers that clamp play it
// exactly); the stored base mesh is shifted by -sum (offset/scale) d_i and the
// rest weights are the offsets, so the rest pose stays v_shaped.
//
// Joints: the AMASS body model (human_body_prior BodyModel.forward) regresses
// the joints from the displaced template, J' = J_regressor (v_shaped + D c).
// Fixed joints (default) keep the betas-only J: the vertex error this costs,
// |sum_k w_ik (a'_k - a_k)| with a_k the translation of the skin transform
// A_k = G_k [I | -J_k], is measured every frame (AnimationClip::dmpl_joint_error).
// Regressed joints animate every joint's local translation so that the
// engine's skin matrix W_k * IBM_k (IBM_k = [I | -J_k], fixed) equals the
// published G'_k [I | -J'_k]: with delta_k = J'_k - J_k,
//   l_k = (J_k - J_p(k)) + delta_k - R_k delta_k   (k > 0),
//   root: (J_0 + trans) + delta_0 - R_0 delta_0 (times the up-axis rotation).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/body_model.h"
#include "core/models/dmpl.h"
#include "core/motions/motion.h"
#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

// What exportAsset (export_asset.h) needs to add the targets.
struct DmplInput {
  const DmplBasis* basis = nullptr;  // null: no DMPL targets
  std::vector<DmplLayout> layout;    // dmplLayout()
  bool animate_joints = false;       // --dmpl-joints regressed
};

// weight = scale * c + offset with the range [min(0, min c), max(0, max c)]
// of direction i over every frame of `motions` mapped to [0, 1]; without any
// coefficients (static export): scale 1, offset 0 (weights 0 = rest).
std::vector<DmplLayout> dmplLayout(int directions,
                                   const std::vector<const Eigen::MatrixXd*>& coefficients);

// Appends the targets dmpl_<i> (i < basis.directions.cols()) to the mesh,
// shifts the base mesh by the offsets, and fills asset->metadata.dmpl.
void addDmplTargets(const BodyModel& model, const DmplBasis& basis,
                    const std::vector<DmplLayout>& layout, bool animate_joints, Asset* asset);

// The coefficients of source position frame + t (linear), first D columns.
Eigen::VectorXd dmplAt(const Motion& motion, int frame, double t, int directions);

// One output frame: morph weights of the DMPL targets, the fixed-joint error,
// and with animate_joints the joints' local translations (root_translation of
// `frame` must be filled; `local` = the frame's local rotations as exported,
// the root's including the up-axis rotation `up`). Errors: the joint
// translations would exceed the memory budget (charged to clip->charge).
Status applyDmplFrame(const Asset& asset, const Eigen::VectorXd& c, const Rotations& local,
                      const Eigen::Matrix3d& up, int frame, AnimationClip* clip);

// Motion coefficients usable with a basis of `directions` columns: errors
// name the motion file `path` (shape, NaN from Motion::dmpls_problem, width
// different from the basis's `directions`, before --dmpl-count, values beyond
// kMaxCoefficient: checkDmplValues, core/models/validate_inputs.h).
Status checkDmplCoefficients(const Motion& motion, const std::string& path, int directions,
                             const std::string& basis_path);

}  // namespace smpl
