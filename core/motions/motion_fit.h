// SMPL-X (and SMPL) fits as fitters write them: SMPLify-X, PIXIE, ExPose
// style `.pkl` (read by the data-only unpickler) or `.npz`, one frame or many,
// with or without a leading batch dimension of 1. Keys (smplx's names):
//   global_orient  (T,3) axis-angle or (T,1,3,3) rotation matrices
//   body_pose      21 joints (SMPL-X / SMPL-H body: (T,63), (T,21,3),
//                  (T,21,3,3)) or 23 joints (SMPL: (T,69), ...); the joint
//                  count gives the layout: 21 -> SMPL-X, 23 -> SMPL
//   left_hand_pose / right_hand_pose
//                  (T,45) or (T,15,3) full axis-angle, (T,C) with 1 <= C < 45
//                  PCA coefficients of the model's hands_componentsl/r (first
//                  C rows), or (T,15,3,3) rotation matrices
//   jaw_pose, leye_pose, reye_pose  (T,3) or (T,1,3,3)
//   betas (1,B) or (B,); transl (T,3); expression (T,E) (baked with --expression-keys)
//   camera_translation (1,3) / camera_rotation (1,3,3) without transl
//                  (SMPLify-X results): the body in camera coordinates,
//                  R_c v + t_c (a per-frame frame change, MotionWorld::CameraYDown)
//   body_pose with 32 values per frame (SMPLify-X with use_vposer): a VPoser
//                  latent, refused ("decode it with VPoser first")
// T comes from body_pose (every leading dimension multiplied); every other
// pose key must have T frames too. Absent parts stay at rest.
//
// Hands follow the authors' reference code (vchoutas/smplx body_models.py,
// SMPLH/SMPLX.forward, axis-angle input):
//   hand = coefficients @ hands_components[:C]       (PCA input only)
//   hand = hand + hands_mean                          (PCA AND full 45-d input,
//                                                      unless flat_hand_mean)
// Rotation-matrix hands are absolute (SMPLXLayer adds no mean). The model
// supplies components and mean, so axis-angle hands wait in Motion::hands
// until resolveFitHands() runs with the model.
#pragma once

#include <string>

#include "core/body_model.h"
#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/motions/motion_layout.h"
#include "core/result.h"

namespace smpl {
namespace motion_detail {

// The row's decode for files with `body_pose` / `global_orient`.
Status decodeFit(const DataNode& d, const std::string& path, Motion* m);

}  // namespace motion_detail

// The table row (core/motions/motion_layout.h): matches `body_pose` or `global_orient`.
const MotionLayout& fitLayout();

// Turns Motion::hands into the hand joints' rotations with the model's PCA
// components and mean (see above); flat_hand_mean: the poses are relative to
// the flat hand (--flat-hand-mean), nothing is added. A model without finger
// joints drops the hands (note). Errors name the motion and the missing key:
//   "fit.pkl: 12 PCA hand coefficients need 'hands_componentsl' in the model m.npz".
// No-op when there is nothing pending.
Status resolveFitHands(const BodyModel& model, bool flat_hand_mean, const std::string& context,
                       Motion* m);

}  // namespace smpl
