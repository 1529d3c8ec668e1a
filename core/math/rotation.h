// Rotations built with the portable libm (libm.h) instead of Eigen's
// AngleAxis / slerp, which call the C library's sin/cos/acos: the same
// formulas as Eigen 3.4's (Geometry/AngleAxis.h toRotationMatrix,
// Geometry/Quaternion.h the AngleAxis constructor and slerp), so only the
// last bits of sin/cos/acos change, and those are the same on every platform.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace smpl {

// The rotation by `angle` (radians) about the unit vector `axis`:
// R = cos(a) I + sin(a) [axis]x + (1 - cos(a)) axis axis^T (Rodrigues).
Eigen::Matrix3d axisAngleMatrix(double angle, const Eigen::Vector3d& axis);

// The same rotation as a unit quaternion (w = cos(a/2), xyz = sin(a/2) axis).
Eigen::Quaterniond axisAngleQuaternion(double angle, const Eigen::Vector3d& axis);

// Spherical linear interpolation from unit quaternion a (t = 0) to b (t = 1)
// on the short path; linear weights when a and b are within 1 - epsilon of
// each other (Eigen's Quaternion::slerp). Not normalised.
Eigen::Quaterniond slerp(const Eigen::Quaterniond& a, double t, const Eigen::Quaterniond& b);

}  // namespace smpl
