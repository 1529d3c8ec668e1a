// Meshcapade SMPLCodec `.smpl` files (the format of their platform and of
// smpl-rs): an npz of camelCase keys, as written by smplcodec's codec.py.
//   smplVersion   int enum: 0 SMPL, 1 SMPLH, 2 SMPLX, 3 SUPR, 4 SMPLPP, 5 SKEL,
//                 6 SMIL, 7 SMPLXS (default 2 when absent, as in the codec).
//                 Read: SMPL and SMIL (24-joint SMPL tree), SMPLH, SMPLX and
//                 SMPLXS (SMPL-X tree); the others have other skeletons: error.
//   gender        int enum: 0 neutral, 1 male, 2 female
//   shapeParameters (B,) betas;  frameCount int;  frameRate float (fps)
//   bodyTranslation (T,3) metres
//   bodyPose      (T,22,3) axis-angle pelvis..right_wrist (SMPL: (T,24,3)).
//                 One joint fewer, (T,21,3) (SMPL: (T,23,3)), is read as the
//                 pose WITHOUT the root: the root rotation then comes from a
//                 `globalOrient` (T,3) key if present, else stays at rest
//                 (with a note). The joint count decides; nothing else does.
//   headPose      (T,3,3) axis-angle of jaw, left eye, right eye (SMPL-X)
//   leftHandPose / rightHandPose (T,15,3) axis-angle, index1..thumb3
//   expressionParameters (T,E)  SMPL-X expression coefficients per frame, baked
//                 as expr_<i> weights with --expression-keys (exporter/expression_targets.h)
// Missing part poses are zeros (rest), as the codec's full_pose fills them.
// A file without bodyPose is a body shape only (no pose data).
#pragma once

#include <string>

#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/motions/motion_layout.h"
#include "core/result.h"

namespace smpl {
namespace motion_detail {

// The row's decode for files with `bodyPose`: fills frames, layout,
// translation, betas, gender, fps (0 when `frameRate` is absent), notes.
Status decodeSmplCodec(const DataNode& d, const std::string& path, Motion* m);

}  // namespace motion_detail

// The table row (core/motions/motion_layout.h): matches `bodyPose`.
const MotionLayout& smplCodecLayout();

}  // namespace smpl
