// WHAM results (yohanshin/WHAM demo.py run(): joblib.dump(results,
// "wham_output.pkl"), results = collections.defaultdict(dict) keyed by
// numpy.int64 track ids from np.unique over the tracker's ids). Per track:
//   pose        (T,72) float32 SMPL axis-angle: camera-frame root + 23 body joints
//   trans       (T,3)  camera-frame SMPL transl (trans_cam - offset: the stored
//                      verts are SMPL(pose, betas) + trans)
//   pose_world  (T,72) world root (Network.rollout(return_y_up=True): Y up) + body
//   trans_world (T,3)  world SMPL transl (as lib/eval/evaluate_emdb.py uses it)
//   betas       (T,10) per frame -> their mean (note)
//   frame_ids   (T,)   int64 source frames (gaps hold the previous frame)
//   verts       (T,6890,3) not read
// --source-params global (default) reads pose_world/trans_world (world Y up,
// note "world frame ('pose_world', 'trans_world'; Y up)"); incam reads
// pose/trans (camera frame, --up -y). A track without pose_world falls back
// to the camera frame (note) unless --source-params global was given (error).
// WHAM's demo renderer recentres on its own mid-hip regressor and drops the
// body to the ground; we do not (docs/motions.md "WHAM"). No rate is stored: 30 fps.
// Detected by content: a dict whose values are all dicts with `pose`,
// `frame_ids` and `trans`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& whamLayout();

}  // namespace smpl
