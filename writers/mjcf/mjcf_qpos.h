// The reference motion of the MJCF writer (mjcf_writer.h) as MuJoCo qpos: one
// row per frame of the asset's clip, in the order MuJoCo numbers the joints of
// the written model (its bodies depth first, children in joint-index order).
//
// Row layout (nq = 7 + 3 (K - 1) with hinges, 7 + 4 (K - 1) with ball joints):
//   root free joint  position (3, metres, Z up: the root joint's world
//                    position, the clip's root translation, or its rest
//                    position when the clip has none, as the BVH writer does)
//                    then quaternion w, x, y, z (Z up)
//   every other body hinges: (a, b, c) with R' = Rx(a) Ry(b) Rz(c), radians in
//                    [-pi, pi]; ball: the quaternion w, x, y, z of R'
// R' = C R C^T is the joint's local rotation R (model axes, Y up) seen in the
// Z-up body frames, C the +90 degree turn about X, (x, y, z) -> (x, -z, y).
// Quaternions have w >= 0.
//
// Hinges: MuJoCo composes a body's joints in their order, each about its axis
// in the frame left by the previous ones (mj_kinematics: xquat = xquat *
// axis-angle quat per joint), so the three hinges _x, _y, _z give
// Rx(a) Ry(b) Rz(c). Angles: a = atan2(-R'_12, R'_22), then M = Rx(-a) R' =
// Ry(b) Rz(c), b = atan2(M_02, M_22), c = atan2(M_10, M_11) (every atan2 in
// [-pi, pi], so within the hinge range). Near b = +-pi/2 (gimbal lock) a and
// c are not unique: a comes from the small R'_12, R'_22 (0 when both are 0)
// and c absorbs the rest, so Rx(a) Ry(b) Rz(c) still equals R' to rounding,
// but a and c can jump between neighbouring frames.
//
// Errors ("MJCF writer: ..."): a clip whose non-root joint moves away from its
// rest offset (--root-bone, --dmpl-joints: MuJoCo's hinge and ball joints hold
// rotations only), tracks shorter than the clip.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

struct MjcfMotion {
  int nq = 0;
  std::vector<double> qpos;   // T x nq, row-major
  std::vector<double> times;  // T seconds
  double fps = 0.0;
  std::vector<std::string> joint_names;  // the MuJoCo joints in qpos order (the free root first)
};

// The written model's bodies (skeleton joints) in MuJoCo's order: depth first
// from the root, children in joint-index order.
std::vector<int> mjcfBodyOrder(const Skeleton& skeleton);

// Hinge angles (a, b, c) with R = Rx(a) Ry(b) Rz(c) (see above); R a rotation.
Eigen::Vector3d mjcfHingeAngles(const Eigen::Matrix3d& r);

// `clip` on `asset`'s skeleton as qpos; `joints` "hinge" or "ball".
Result<MjcfMotion> mjcfMotion(const Asset& asset, const AnimationClip& clip,
                              const std::string& joints);

}  // namespace smpl
