// PHALP / 4D-Humans tracking results (brjathu/PHALP phalp/trackers/PHALP.py
// track(): joblib.dump(final_visuals_dic, pkl_path, compress=3), a dict keyed
// by frame path in video order; shubham-goel/4D-Humans track.py). Per frame:
//   time          int, the frame index
//   tid           ids of every confirmed track (a list)
//   tracked_time  per `tid` entry, frames since its last detection
//   tracked_ids   ids detected in this frame
//   smpl[i]       HMR2 parameters of entry i: global_orient (1,3,3),
//                 body_pose (23,3,3) rotation matrices, betas (10,)
//   camera[i]     (3,) pred_cam_t (phalp/models/hmar/hmar.py get_3d_parameters:
//                 the body's translation in a camera of focal length 5000 px),
//                 added to the vertices like an SMPL transl
//   appe, loca, pose, bbox, 3d_joints, mask, ... (not read)
// A detection of track `id` in a frame is its entry i in `tid` with
// tracked_time[i] == 0, exactly phalp/utils/utils_tracks.py get_tracks;
// entries with tracked_time > 0 repeat the last detection and are not rows
// (the clip holds the previous one there). Camera frame (--up -y); betas:
// the mean of the track's detections; no rate stored: 30 fps. A file with no
// detection at all is refused: "no tracked person (no frame lists a
// 'tracked_ids' entry)". --source-params global is refused.
// Detected by content: a dict whose values are all dicts with `tid`,
// `tracked_time` and `smpl`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& phalpLayout();

}  // namespace smpl
