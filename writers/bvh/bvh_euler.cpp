// ZXY Euler angles of a rotation (bvh_euler.h).
#include "writers/bvh/bvh_euler.h"

#include <algorithm>
#include <cmath>

#include "core/math/libm.h"
#include "core/math/rotation.h"

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

// `angle` plus the whole turns that bring it nearest `target`.
double nearTurn(double angle, double target) {
  return angle + 2.0 * kPi * std::round((target - angle) / (2.0 * kPi));
}

EulerZxy shiftedNear(const EulerZxy& e, const EulerZxy& target) {
  return EulerZxy{nearTurn(e.z, target.z), nearTurn(e.x, target.x), nearTurn(e.y, target.y)};
}

double distance2(const EulerZxy& a, const EulerZxy& b) {
  return (a.z - b.z) * (a.z - b.z) + (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

// The principal angles; *locked: cos x below 1e-7, where only z + y (x = 90
// degrees) or z - y (x = -90) is defined and y = 0 is returned.
EulerZxy principal(const Eigen::Quaterniond& q, bool* locked) {
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  const double s = std::clamp(r(2, 1), -1.0, 1.0);
  EulerZxy e;
  e.x = libm::asin(s);
  const double c = libm::hypot(r(2, 0), r(2, 2));  // |cos x|
  *locked = !(c > 1e-7);  // below, the lock formula errs by at most c radians
  if (!*locked) {
    e.z = libm::atan2(-r(0, 1), r(1, 1));
    e.y = libm::atan2(-r(2, 0), r(2, 2));
  } else {
    e.z = libm::atan2(r(1, 0), r(0, 0));
    e.y = 0.0;
  }
  return e;
}

// Gimbal lock: of the angles with z + y = a.z (x = +90) or z - y = a.z (x =
// -90), whole turns included, the nearest `previous`.
EulerZxy lockedNear(const EulerZxy& a, const EulerZxy& p) {
  EulerZxy e;
  e.x = nearTurn(a.x, p.x);
  if (a.x > 0) {
    const double sum = nearTurn(a.z, p.z + p.y);
    e.y = 0.5 * (sum - p.z + p.y);
    e.z = sum - e.y;
  } else {
    const double difference = nearTurn(a.z, p.z - p.y);
    e.y = 0.5 * (p.z - difference + p.y);
    e.z = difference + e.y;
  }
  return e;
}

}  // namespace

EulerZxy eulerZxyOf(const Eigen::Quaterniond& q) {
  bool locked = false;
  return principal(q, &locked);
}

EulerZxy eulerZxyNear(const Eigen::Quaterniond& q, const EulerZxy& previous) {
  bool locked = false;
  const EulerZxy a = principal(q, &locked);
  if (locked) return lockedNear(a, previous);
  const EulerZxy b{a.z + kPi, kPi - a.x, a.y + kPi};  // the same rotation
  const EulerZxy near_a = shiftedNear(a, previous), near_b = shiftedNear(b, previous);
  return distance2(near_b, previous) < distance2(near_a, previous) ? near_b : near_a;
}

Eigen::Quaterniond quaternionOfZxy(const EulerZxy& e) {
  return axisAngleQuaternion(e.z, Eigen::Vector3d::UnitZ()) *
         axisAngleQuaternion(e.x, Eigen::Vector3d::UnitX()) *
         axisAngleQuaternion(e.y, Eigen::Vector3d::UnitY());
}

}  // namespace smpl
