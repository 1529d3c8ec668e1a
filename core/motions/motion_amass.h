// AMASS and plain pose files (.npz, .pkl, .json):
//   poses        (T,3J) or (T,J,3) axis-angle, or (T,J,3,3) rotation matrices,
//                J = 24 (SMPL), 52 (SMPL-H release, (T,156)), 55 (SMPL-X
//                release, (T,165)) or 16 (MANO); the joint count gives the layout
//   or the AMASS SMPL-X split keys root_orient (T,3), pose_body (T,63),
//                pose_jaw (T,3), pose_eye (T,6), pose_hand (T,90), joined in
//                that order into (T,165)
//   trans (T,3) metres; betas (B,) or per frame (T,B) (core/models/betas_rows.h);
//   gender; dmpls (T,D) DMPL coefficients (kept for --dmpl, core/models/dmpl.h);
//   mocap_framerate / mocap_frame_rate / fps: the rate. An AMASS file (a
//   mocap_frame* rate, `gender` or the split keys) is a Z-up capture world.
#pragma once

#include <string>

#include "core/motions/motion_layout.h"

namespace smpl {

// The table row (core/motions/motion_layout.h): matches `poses` or `root_orient`.
const MotionLayout& amassLayout();

// `poses` (T,3J) or (T,J,3) axis-angle, or (T,J,3,3) rotation matrices, into
// m->frames in the model's joint order, and m->layout from J. Shared with the
// bare pose array row (motion_bare_poses.h), which reads its array the same
// way. Errors name path and 'poses'; a (T,46) array is refused as SKEL's.
Status decodeRotations(const Array& poses, const std::string& path, Motion* m);

}  // namespace smpl
