// VIBE results (mkocabas/VIBE demo.py: joblib.dump(vibe_results,
// "vibe_output.pkl"), a dict keyed by int person ids from
// multi-person-tracker). Per person:
//   pose      (T,72) float32 SMPL axis-angle (theta[:, 3:75]), camera frame
//   betas     (T,10) per frame -> their mean (note)
//   frame_ids (T,)   source frames
//   pred_cam (T,3), orig_cam (T,4)  weak-perspective image cameras (not read)
//   verts, joints3d, joints2d (None with bbox tracking), joints2d_img_coord, bboxes (not read)
// No 3-D translation is stored: as VIBE's own exporter (lib/utils/fbx_output.py
// process_poses: trans = zeros) the translation is zero (note); camera frame
// (--up -y, as lib/utils/renderer.py turns the mesh). --source-params global
// is refused (no world-frame parameters). No rate is stored: 30 fps.
// Detected by content: a dict whose values are all dicts with `pose`,
// `frame_ids`, `orig_cam` and no `trans` (WHAM's tracks have `trans`).
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& vibeLayout();

}  // namespace smpl
