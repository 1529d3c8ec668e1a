#include "core/math/rotation.h"

#include <cmath>
#include <limits>

#include "core/math/libm.h"

namespace smpl {

Eigen::Matrix3d axisAngleMatrix(double angle, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d sin_axis = libm::sin(angle) * axis;
  const double c = libm::cos(angle);
  const Eigen::Vector3d cos1_axis = (1.0 - c) * axis;
  Eigen::Matrix3d r;
  double tmp = cos1_axis.x() * axis.y();
  r(0, 1) = tmp - sin_axis.z();
  r(1, 0) = tmp + sin_axis.z();
  tmp = cos1_axis.x() * axis.z();
  r(0, 2) = tmp + sin_axis.y();
  r(2, 0) = tmp - sin_axis.y();
  tmp = cos1_axis.y() * axis.z();
  r(1, 2) = tmp - sin_axis.x();
  r(2, 1) = tmp + sin_axis.x();
  r.diagonal() = (cos1_axis.cwiseProduct(axis)).array() + c;
  return r;
}

Eigen::Quaterniond axisAngleQuaternion(double angle, const Eigen::Vector3d& axis) {
  const double half = 0.5 * angle;
  Eigen::Quaterniond q;
  q.w() = libm::cos(half);
  q.vec() = libm::sin(half) * axis;
  return q;
}

Eigen::Quaterniond slerp(const Eigen::Quaterniond& a, double t, const Eigen::Quaterniond& b) {
  const double one = 1.0 - std::numeric_limits<double>::epsilon();
  const double d = a.dot(b);
  const double abs_d = std::abs(d);
  double scale0, scale1;
  if (abs_d >= one) {
    scale0 = 1.0 - t;
    scale1 = t;
  } else {
    const double theta = libm::acos(abs_d);  // the angle between the two quaternions
    const double sin_theta = libm::sin(theta);
    scale0 = libm::sin((1.0 - t) * theta) / sin_theta;
    scale1 = libm::sin(t * theta) / sin_theta;
  }
  if (d < 0) scale1 = -scale1;
  return Eigen::Quaterniond(scale0 * a.coeffs() + scale1 * b.coeffs());
}

}  // namespace smpl
