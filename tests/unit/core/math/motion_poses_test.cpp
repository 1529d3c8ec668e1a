// sampleMotionPoses (core/math/motion_poses.h): deterministic, inside each
// joint's range of motion, and correlated the way captured motion is (knees
// bend one way, hips and knees flex together when sitting, legs swing in
// opposite phase), unlike the uniform poses of pose_sampler.h.
#include "core/math/motion_poses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/joint_names.h"

namespace smpl {
namespace {

int indexOf(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  return int(it - names.begin());
}

// Pearson correlation of a(i) and b(i) over the poses.
double correlation(const std::vector<Eigen::VectorXd>& poses, int a, int b) {
  const double n = double(poses.size());
  double ma = 0, mb = 0;
  for (const Eigen::VectorXd& p : poses) ma += p[a] / n, mb += p[b] / n;
  double sab = 0, saa = 0, sbb = 0;
  for (const Eigen::VectorXd& p : poses) {
    sab += (p[a] - ma) * (p[b] - mb);
    saa += (p[a] - ma) * (p[a] - ma);
    sbb += (p[b] - mb) * (p[b] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST(MotionPoses, SameSeedSamePosesOtherSeedOthers) {
  const std::vector<std::string>& names = canonicalJointNames(ModelKind::Smpl);
  const auto a = sampleMotionPoses(names, 8, 42), b = sampleMotionPoses(names, 8, 42);
  const auto c = sampleMotionPoses(names, 8, 43);
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(a[0].size(), 3 * Eigen::Index(names.size()));
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i] == b[i]);
  EXPECT_FALSE(a[0] == c[0]);
}

TEST(MotionPoses, JointsStayInTheirRangesAndMoveTogether) {
  const std::vector<std::string>& names = canonicalJointNames(ModelKind::Smpl);
  const auto poses = sampleMotionPoses(names, 2000, 7);
  const int lhip = indexOf(names, "left_hip"), rhip = indexOf(names, "right_hip");
  const int lknee = indexOf(names, "left_knee"), lelbow = indexOf(names, "left_elbow");
  const int relbow = indexOf(names, "right_elbow"), spine = indexOf(names, "spine2");
  double knee_max = 0.0, hip_min = 0.0;
  for (const Eigen::VectorXd& p : poses) {
    EXPECT_GE(p[3 * lknee], 0.0);       // knees do not hyperextend
    EXPECT_LE(p[3 * lelbow + 1], 0.0);  // the left elbow bends about -y ...
    EXPECT_GE(p[3 * relbow + 1], 0.0);  // ... the right one about +y
    EXPECT_LE(std::abs(p[3 * spine + 2]), 0.2 + 1e-12);
    knee_max = std::max(knee_max, p[3 * lknee]);
    hip_min = std::min(hip_min, p[3 * lhip]);
  }
  EXPECT_GT(knee_max, 1.5);  // sitting: far beyond uniform +-0.6 rad poses
  EXPECT_LT(hip_min, -1.2);
  EXPECT_LT(correlation(poses, 3 * lhip, 3 * lknee), -0.5);  // hips flex as knees bend
  EXPECT_GT(correlation(poses, 3 * lhip, 3 * rhip), 0.0);    // sitting moves both hips
}

TEST(MotionPoses, UnknownJointsGetSmallIndependentRotations) {
  const auto poses = sampleMotionPoses({"root", "bone_a", "bone_b"}, 500, 3);
  for (const Eigen::VectorXd& p : poses)
    for (Eigen::Index i = 3; i < p.size(); ++i) EXPECT_LE(std::abs(p[i]), 0.3);
  EXPECT_LT(std::abs(correlation(poses, 3, 6)), 0.15);
}

}  // namespace
}  // namespace smpl
