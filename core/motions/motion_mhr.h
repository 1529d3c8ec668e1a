// SAM 3D Body's output is MHR (Meta's Momentum Human Rig), not SMPL: its
// `mhr_model_params` (204: translation, rotation, 130 pose and 68 scale
// parameters), `shape_params` (45), `body_pose_params` (133) and
// `hand_pose_params` (108) drive another body model, and its
// `pred_vertices` are MHR's 18439 vertices. No SMPL-family model can play
// them. MHR's own repository converts them (tools/mhr_smpl_conversion) into
// SMPL-X parameters, which export exactly. Recognised so that the file is
// refused with that way forward instead of "keys found: ...":
//   "<file>: MHR parameters (SAM 3D Body), not SMPL: convert them with MHR's
//    tools/mhr_smpl_conversion, then export its result (docs/motions.md
//    "SAM 3D Body")"
// Both the per-person dict (estimator.process_one_image's list items) and a
// pickled list of them are recognised.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

// The table row: a refusal (decode always fails with the message above).
const MotionLayout& mhrLayout();

}  // namespace smpl
