// BEAT2 / EMAGE talking-body motions (PantoMatrix/PantoMatrix
// emage_utils/motion_io.py beat_format_save: np.savez(betas, poses,
// expressions, trans, model='smplx2020', gender, mocap_frame_rate=30)):
//   poses        (T,165) SMPL-X axis-angle: global 0:3, body 3:66, jaw 66:69,
//                eyes 69:75, left hand 75:120, right hand 120:165
//   expressions  (T,E) SMPL-X expression coefficients (E = 100), baked with
//                --expression-keys (exporter/expression_targets.h)
//   trans (T,3); betas (300,); gender; mocap_frame_rate (30)
// Conventions of its body-model call (emage_utils/npz2pose.py _get_smplx_model:
// smplx.create(use_pca=False, flat_hand_mean=False, num_betas=300,
// num_expression_coeffs=100)): the hands are relative to the model's
// hands_mean (added, unless --flat-hand-mean); a Y-up world (not AMASS's Z up).
// Recognised before AMASS: `poses` with `expressions` or `model`, and none of
// AMASS's `surface_model_type`, `root_orient`, `pose_body`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& beat2Layout();

}  // namespace smpl
