// PromptHMR video results (yufu-wang/PromptHMR pipeline/pipeline.py
// Pipeline.__call__: joblib.dump(self.results, f'{seq_folder}/results.pkl')).
// A dict; the keys read:
//   people        {track id: person}; the ids come from the tracker
//                 (pipeline/tools.py: int object ids) and are the track ids
//   camera_world  pipeline/world.py world_hps_estimation (then
//                 pipeline/postprocessing.py post_optimization): Rcw (N,3,3),
//                 Tcw (N,3) world-to-camera of each of the video's N frames;
//                 img_focal (px), img_center (cx, cy) (px)
// Per person:
//   frames        (T,) int source frames of the track's rows
//   smplx_world   {pose (T,165) axis-angle of the 55 SMPL-X joints, shape
//                 (T,10) (every row the track's mean), trans (T,3) SMPL-X transl}
//                 in PromptHMR's world: gravity-aligned, Y up, the floor at
//                 y = 0 (world.py: the camera's y-down frame turned by
//                 diag(1,-1,-1), fit_floor_height(..., 'y') subtracted)
//   smplx_cam     {pose (T,75) = root, 21 body, jaw, eyes (phmr_vid.py: the
//                 video model predicts no hands), rotmat (T,55,3,3) the same
//                 rotations with zero matrices for the hands, shape, trans}:
//                 the camera frame (x right, y down, z forward)
// The body model is SMPL-X with flat_hand_mean=True (pipeline.py), so the
// finger rotations of `pose` are absolute: put as they are, no mean added.
// --source-params global (default) reads smplx_world; incam reads smplx_cam
// (--up -y). A person without smplx_world falls back to smplx_cam (note)
// unless global was asked for (error). Every other per-person key (bboxes,
// masks, keypoints_2d, vitpose, the image model's smplx_pose / smplx_transl /
// smplx_betas, prhmr_img_feats, track_id, smplx_cam's rotmat, contact,
// static_conf_logits) is named in the note "ignored: ...".
// MotionSet::camera: global, frame f's camera-to-world rotation Rcw[f]^T and
// centre -Rcw[f]^T Tcw[f] (as PromptHMR's .mcs export computes them,
// pipeline/mcs_export_cam.py add_camera_animation; Rwc/Twc are not read:
// post_optimization stores Twc = -Rcw Tcw, not the centre); incam, the
// camera at the origin with identity rotation (the bodies are in its frame).
// yfov = 2 atan(cy / f), aspect = cx / cy (mcs_export_cam.py
// add_camera_intrinsics: the image is taken as twice the principal point).
// No rate is stored (the config's fps is not in the file): 30 fps.
// Detected by content: a dict with a `people` dict whose values are dicts with
// `smplx_world` or `smplx_cam` (an empty `people` beside a `camera_world`:
// refused, "no tracked person").
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& promptHmrLayout();

}  // namespace smpl
