// ROMP and BEV video results (Arthur151/ROMP simple_romp/romp/utils.py
// save_video_results: np.savez(results=..., sequence_results=...), two 0-d
// object members, read as trees):
//   results           frame file name -> per-frame dict: smpl_thetas (N,72),
//                     smpl_betas (N,10) (BEV: (N,11)), cam_trans (N,3),
//                     track_ids (N,) with tracking, cam, verts, joints, ... (not read)
//   sequence_results  numpy.int32 track id -> {frame_id: [..], and per key of
//                     the frame dict a list of that person's rows}
// Tracks come from sequence_results (rows at `frame_id`); when it is empty,
// person 0 of each frame in sorted frame-name order, the frame being the
// position in that order (as simple_romp/tools/convert2fbx.py; note).
// Poses: SMPL axis-angle (ROMP zeroes the hand joints). Vertices as
// simple_romp/vis_human/main.py renders them, verts + cam_trans, in the
// camera frame (--up -y):
//   ROMP (10 betas): verts are plain SMPL, cam_trans is the SMPL transl;
//   BEV (11 betas, SMPL+A; source layout "bev"): bev/post_parser.py
//     SMPLA_parser root-aligns the vertices on the mid-point of its hip
//     joints; we anchor on the model's own hips: Motion::translation_anchor
//     = {left_hip, right_hip}, the bake places their posed mid-point at
//     cam_trans (note). betas[10], the SMPL+A age blend, is dropped (note);
//     a track whose mean age is above 0.8 is BEV's infant SMIL body
//     (SMPLA_parser baby_thresh), not an SMPL body: left out with a note, and
//     a file with only such tracks is refused.
// Betas: the mean of each track's rows. Rate: 24 fps (convert2fbx.py
// fps_source) unless --source-fps. --source-params global is refused.
// Detected by the .npz member names `results` and `sequence_results`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& rompLayout();

}  // namespace smpl
