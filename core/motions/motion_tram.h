// TRAM per-track results (yufu-wang/tram scripts/estimate_humans.py:
// np.save(f'{hps_folder}/hps_track_{k}.npy', results), results from
// lib/models/hmr_vimo.py HMR_VIMO.inference: a dict of torch tensors pickled
// inside the .npy, see docs/motions.md "Containers"):
//   pred_rotmat (T,24,3,3) SMPL rotation matrices (camera frame)
//   pred_trans  (T,1,3)    SMPL transl (get_trans), camera frame
//   pred_shape  (T,10)     betas per frame -> their mean, as visualize_tram does
//   frame       (T,)       int64 source frames (chunks: gaps hold the previous frame)
//   pred_cam (T,3), pred_pose (T,144) 6D  not read
// World (lib/pipeline/visualization.py visualize_tram, scripts/estimate_camera.py,
// lib/camera/est_gravity.py): when <dir of the file>/../camera.npy exists
// (np.save of a dict: world_cam_R (N,3,3), world_cam_T (N,3) camera-to-world,
// Y up) the world vertices are world_cam_R[frame] v + world_cam_T[frame]:
// Motion::world_rotation / world_translation per row, MotionWorld::Y (note).
// Without camera.npy (note naming the expected path) or with
// --source-params incam: the camera frame (--up -y); --source-params global
// without camera.npy is an error. A `frame` beyond camera.npy's N is refused
// naming both files. TRAM's renderer also lowers the scene to its lowest
// vertex; we do not. No rate stored: 30 fps. One person per file, no id.
// Detected by content: a dict with `pred_rotmat`, `pred_trans` and `frame`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& tramLayout();

}  // namespace smpl
