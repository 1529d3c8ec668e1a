// BVH rotation channels (writers/bvh/bvh_euler.h): the angles of R = Rz Rx Ry,
// checked against rotation matrices written out here from the definition, and
// continuity across frames (no whole-turn jumps, the other triple at +-90 x).
#include "writers/bvh/bvh_euler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The elementary rotations as matrices, from their definition.
Eigen::Matrix3d rz(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}
Eigen::Matrix3d rx(double a) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return m;
}
Eigen::Matrix3d ry(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return m;
}
Eigen::Matrix3d matrixOf(const EulerZxy& e) { return rz(e.z) * rx(e.x) * ry(e.y); }

TEST(BvhEuler, AnglesOfKnownRotations) {
  const EulerZxy e = eulerZxyOf(Eigen::Quaterniond(rz(0.3) * rx(0.2) * ry(-0.1)));
  EXPECT_NEAR(e.z, 0.3, 1e-14);
  EXPECT_NEAR(e.x, 0.2, 1e-14);
  EXPECT_NEAR(e.y, -0.1, 1e-14);
  // A quarter turn about Y alone is all y; about Z alone all z.
  EXPECT_NEAR(eulerZxyOf(Eigen::Quaterniond(ry(kPi / 2))).y, kPi / 2, 1e-14);
  EXPECT_NEAR(eulerZxyOf(Eigen::Quaterniond(rz(-2.5))).z, -2.5, 1e-14);
  // q and -q are the same rotation.
  const Eigen::Quaterniond q(rz(1.0) * rx(-0.4) * ry(2.0));
  const EulerZxy a = eulerZxyOf(q), b = eulerZxyOf(Eigen::Quaterniond(-q.coeffs()));
  EXPECT_NEAR(a.z, b.z, 1e-14);
  EXPECT_NEAR(a.x, b.x, 1e-14);
  EXPECT_NEAR(a.y, b.y, 1e-14);
}

TEST(BvhEuler, RandomRotationsComeBack) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Quaterniond q = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
    const EulerZxy e = eulerZxyOf(q);
    EXPECT_LE(std::abs(e.x), kPi / 2 + 1e-15);
    EXPECT_LE(std::abs(e.z), kPi + 1e-15);
    EXPECT_LE(std::abs(e.y), kPi + 1e-15);
    EXPECT_LT((matrixOf(e) - q.toRotationMatrix()).cwiseAbs().maxCoeff(), 1e-12) << i;
    EXPECT_LT(std::abs(std::abs(quaternionOfZxy(e).dot(q)) - 1.0), 1e-12) << i;
    // Near any previous frame the angles still give the rotation.
    const EulerZxy near = eulerZxyNear(q, EulerZxy{7.0 * n(rng), 7.0 * n(rng), 7.0 * n(rng)});
    EXPECT_LT((matrixOf(near) - q.toRotationMatrix()).cwiseAbs().maxCoeff(), 1e-12) << i;
  }
}

TEST(BvhEuler, GimbalLockKeepsTheRotation) {
  for (double x : {kPi / 2, -kPi / 2, kPi / 2 - 1e-9}) {
    const Eigen::Matrix3d r = rz(0.7) * rx(x) * ry(-0.2);
    const EulerZxy e = eulerZxyOf(Eigen::Quaterniond(r));
    EXPECT_LT((matrixOf(e) - r).cwiseAbs().maxCoeff(), 1e-7) << x;
  }
}

TEST(BvhEuler, FramesAreContinuous) {
  // A turn about Y through 180 degrees and on to 350: y grows, never wraps.
  EulerZxy previous;
  for (int i = 0; i <= 70; ++i) {
    const double y = i * 5.0 * kPi / 180.0;
    const EulerZxy e = eulerZxyNear(Eigen::Quaterniond(rx(0.1) * ry(y)), previous);
    EXPECT_NEAR(e.y, y, 1e-12) << i;
    EXPECT_NEAR(e.x, 0.1, 1e-12) << i;
    previous = e;
  }
  // x through +90 degrees: the other triple (z + 180, 180 - x, y + 180) continues it.
  previous = EulerZxy();
  for (int i = 0; i <= 36; ++i) {
    const double x = i * 5.0 * kPi / 180.0;
    const Eigen::Matrix3d r = rz(0.2) * rx(x) * ry(0.3);
    const EulerZxy e = eulerZxyNear(Eigen::Quaterniond(r), previous);
    EXPECT_LT((matrixOf(e) - r).cwiseAbs().maxCoeff(), 1e-9) << i;
    if (i > 0) {
      EXPECT_LT(std::abs(e.x - previous.x), 0.2) << i;  // 5 degrees a step, none skipped
      EXPECT_LT(std::abs(e.z - previous.z), 0.2) << i;
      EXPECT_LT(std::abs(e.y - previous.y), 0.2) << i;
    }
    previous = e;
  }
  EXPECT_NEAR(previous.x, kPi, 1e-9);  // past the lock: x runs on to 180 degrees
}

}  // namespace
}  // namespace smpl
