// HaMeR hands (geopavlakos/hamer): MANO parameters of hands seen in images.
// hamer/models/hamer.py forward_step returns pred_mano_params = {global_orient
// (B,1,3,3), hand_pose (B,15,3,3), betas (B,10)} of the RIGHT MANO
// (hamer/models/mano_wrapper.py: smplx MANOLayer, pose2rot=False: rotation
// matrices, no mean pose added); demo.py adds `right` / `is_right` (B,) and
// pred_cam_t_full (B,3), the camera translation in the full image (OpenCV
// camera axes), and shows a left hand as the right hand mirrored by
// S = diag(-1,1,1) (verts[:,0] = (2*is_right-1)*verts[:,0], faces re-wound).
// Downstream scripts save these with np.savez or pickle, at the top level, as
// a nested `pred_mano_params` dict, or flattened as `pred_mano_params.<name>`.
//
// Read here:
//   global_orient (N,1,3,3) or (N,3,3), hand_pose (N,15,3,3), betas (N,B):
//     rows of the right MANO, row-major rotation matrices (v' = R v)
//   is_right or right (N,): > 0.5 is a right hand (absent: right, noted)
//   pred_cam_t_full (N,3): v = LBS + t; else pred_cam_t (the crop camera's,
//     noted); else zero (noted). Camera coordinates: MotionWorld::CameraYDown.
// One file: its N rows are the frames of one hand (all of one side; mixed
// sides are refused). One frame of a --motion-sequence
// (MotionOptions::frame_file): its rows are that frame's hands, in the demo's
// order (per person, left then right); the k-th row of a side joins track
// 2k + (1 if right else 0): HaMeR does not track hands.
// A left hand's rotations are given as the left hand's own pose, S R S for
// every joint (MANO_LEFT(S R S) = S MANO_RIGHT(R)), with Motion::hand = "left";
// the export mirrors the model when its side differs (request/,
// core/math/mirror_model.h), so a left hand on MANO_RIGHT is HaMeR's mirrored mesh.
// Detection: hand_pose and global_orient (any of the three places), or an
// undecoded `pred_mano_params` member, and no body_pose.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& hamerLayout();

}  // namespace smpl
