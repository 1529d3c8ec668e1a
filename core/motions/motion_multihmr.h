// Multi-HMR per-image results (naver/multi-hmr model.py Model.forward: one
// dict per detected person; demo.py keeps them in a list `humans`), saved one
// file per image with the persons' values stacked (np.savez(f, rotvec=...,
// shape=..., ...), or the same dict pickled). The keys read:
//   rotvec        (P,53,3) or (P,159) axis-angle: global orient, 21 body, 15
//                 left hand, 15 right hand, jaw (blocks/smpl_layer.py
//                 SMPL_Layer.forward: pose[:,1:22] body, [22:37] left hand,
//                 [37:52] right hand, [52:53] jaw); mapped by joint name onto
//                 the SMPL-X joints; the eyes stay at rest (bm_x.leye_pose)
//   shape         (P,B) SMPL-X betas (B = 10)
//   expression    (P,E) SMPL-X expression coefficients (baked with --expression-keys)
//   transl_pelvis (P,1,3) or (P,3) metres: the posed pelvis joint in the camera
//                 frame (j3d_cam[:,0]): SMPL_Layer.forward poses the body with
//                 a zero global orient, turns it by R about the pelvis J_0 and
//                 moves the pelvis there, so v = R (LBS_0(v) - J_0) +
//                 transl_pelvis: the SMPL-X transl is transl_pelvis - J_0(betas)
//                 (Motion::translation_anchor {"pelvis"}: the bake knows J_0)
// Not read: transl (the primary keypoint's location, the head by default:
// not the body's translation), scores, loc, dist (detection), v3d, j3d, j2d
// (the posed mesh and joints); a note names those the file has.
// The model is SMPL-X with flat_hand_mean=True (SMPL_Layer: smplx.create(...,
// flat_hand_mean=True)): the finger rotations are absolute, put as they are.
// Every person a track, ids 0..P-1 in row order (Multi-HMR does not track
// persons across images: a folder read with --motion-sequence joins row p of
// each image into track p; an image with zero rows adds nothing there, and is
// refused alone). Camera frame (x right, y down, z forward): --up -y.
// No rate is stored (one image): 30 fps in a sequence.
// Detected by content: `rotvec` and `transl_pelvis`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& multiHmrLayout();

}  // namespace smpl
