// SMPLer-X per-frame results (caizhongang/SMPLer-X main/inference.py:
// np.savez(f'{frame:05}_{bbox_id}.npz', **smplx_pred) under smplx/, one file
// per frame and detection; meta/<same>.json beside, not read). Keys, exactly
// these ten (smplx's names): global_orient (1,3), body_pose (21,3),
// left_hand_pose / right_hand_pose (15,3), jaw_pose (1,3), leye_pose /
// reye_pose (1,3), betas (1,10), expression (1,10), transl (1,3).
// Each file is read as a fit (motion_fit.h): smplx.create(use_pca=False)
// with smplx's default flat_hand_mean=False adds hands_mean to the 45-d
// hands (--flat-hand-mean turns it off); expression baked with
// --expression-keys. As one file of a --motion-sequence (MotionOptions::
// frame_file): main/SMPLer_X.py get_coord, mesh_cam = vertices + transl,
// is the camera frame (--up -y), layout "smplerx", and a note says the file
// suffix is a detection index (non_max_suppression order), not a tracked
// identity; --source-params global is refused there (no world-frame
// parameters). A single file given to --motion stays a fit (layout "fit", Y up:
// give --up -y), since its keys alone do not tell it from other fits.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& smplerxLayout();

}  // namespace smpl
