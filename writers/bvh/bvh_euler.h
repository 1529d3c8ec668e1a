// BVH rotation channels: a joint's local rotation as three Euler angles in the
// channel order Zrotation Xrotation Yrotation (docs/file-contract.md "BVH"),
// the order Blender's and MotionBuilder's BVH readers and the CMU files use.
// The file lists the channels in that order and means R = Rz(z) Rx(x) Ry(y)
// (rotations about the parent's fixed axes, applied Y first, then X, then Z),
// which is how Blender's importer reads them (Euler order 'YXZ' of the
// channels reversed, io_anim_bvh/import_bvh.py).
//
// Decomposition of R = Rz Rx Ry (rows r, columns c, R(2,1) = sin x):
//   x = asin(R21), z = atan2(-R01, R11), y = atan2(-R20, R22);
//   at x = +-90 degrees (cos x < 1e-7, gimbal lock) y = 0 and z = atan2(R10, R00).
// Successive frames are made continuous: of the two angle triples that give
// one rotation, (z, x, y) and (z + 180, 180 - x, y + 180), each angle shifted
// by whole turns towards the previous frame's, the one nearest the previous
// frame is written (no 360-degree jumps an importer would interpolate across);
// in gimbal lock, where only z + y (or z - y) is fixed, the split of it
// nearest the previous frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace smpl {

// Angles in radians, named by axis; R = Rz(z) Rx(x) Ry(y).
struct EulerZxy {
  double z = 0.0, x = 0.0, y = 0.0;
};

// The principal angles of unit quaternion `q` (normalised here; q and -q give
// the same angles): x in [-pi/2, pi/2], z and y in (-pi, pi].
EulerZxy eulerZxyOf(const Eigen::Quaterniond& q);

// The angles of `q` nearest `previous` (sum of squared differences) among both
// triples of q and their whole-turn shifts: the next frame of a continuous track.
EulerZxy eulerZxyNear(const Eigen::Quaterniond& q, const EulerZxy& previous);

// Rz(z) Rx(x) Ry(y) as a quaternion (the inverse of eulerZxyOf, for checks).
Eigen::Quaterniond quaternionOfZxy(const EulerZxy& e);

}  // namespace smpl
