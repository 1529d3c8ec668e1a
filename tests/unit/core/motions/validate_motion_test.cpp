// A loaded motion's range checks: each bound refuses what it must and keeps what it must.
#include "core/motions/validate_motion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace smpl {
namespace {

Motion motionWith(const Eigen::Matrix3d& r, size_t frame = 3, size_t joint = 5) {
  Motion m;
  m.layout = ModelKind::Smpl;
  m.fps = 30;
  m.frames.assign(6, Rotations(24, Eigen::Matrix3d::Identity()));
  m.translation.assign(6, Eigen::Vector3d::Zero());
  m.frames[frame][joint] = r;
  return m;
}

TEST(ValidateInputs, ZeroScaledAndReflectedMatricesAreRefusedWithFrameAndJoint) {
  for (const Eigen::Matrix3d& bad :
       {Eigen::Matrix3d(Eigen::Matrix3d::Zero()), Eigen::Matrix3d(2 * Eigen::Matrix3d::Identity()),
        Eigen::Matrix3d(Eigen::Vector3d(1, 1, -1).asDiagonal()),
        Eigen::Matrix3d(1.01 * Eigen::Matrix3d::Identity())}) {
    Motion m = motionWith(bad);
    Status st = checkMotionValues(&m, "walk.npz");
    ASSERT_FALSE(st) << bad;
    EXPECT_EQ(st.message().rfind(
                  "walk.npz: 'poses' frame 3 joint 5 (right_knee) is not a rotation matrix", 0),
              0u)
        << st.message();
  }
}

TEST(ValidateInputs, NearRotationIsReorthonormalised) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d noisy = r;
  noisy(0, 1) += 2e-4;  // ||R^T R - I|| about 3e-4: float storage noise, within 1e-3
  Motion m = motionWith(noisy);
  ASSERT_TRUE(checkMotionValues(&m, "walk.npz"));
  const Eigen::Matrix3d fixed = m.frames[3][5];
  EXPECT_LT((fixed.transpose() * fixed - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(fixed.determinant(), 1.0, 1e-12);
  EXPECT_LT((fixed - r).norm(), 3e-4);
}

TEST(ValidateInputs, TranslationsBetasAndFpsOfAMotion) {
  Motion m = motionWith(Eigen::Matrix3d::Identity());
  ASSERT_TRUE(checkMotionValues(&m, "walk.npz"));
  m.translation[2].y() = 2e4;
  Status st = checkMotionValues(&m, "walk.npz");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message(),
            "walk.npz: 'trans' frame 2 is 20000 m; expected finite values within 10000 m");
  m = motionWith(Eigen::Matrix3d::Identity());
  m.betas = {0.1, 1e300};
  st = checkMotionValues(&m, "walk.npz");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message().rfind("walk.npz: 'betas'[1] is 1e+300", 0), 0u) << st.message();
  m = motionWith(Eigen::Matrix3d::Identity());
  m.fps = 0.001;
  EXPECT_FALSE(checkMotionValues(&m, "walk.npz"));
}

}  // namespace
}  // namespace smpl
