// The MJCF writer's qpos rows (writers/mjcf/mjcf_qpos.h): MuJoCo's body
// order, the Z-up turn of the root and of local rotations, the hinge angle
// split R = Rx(a) Ry(b) Rz(c) (also at gimbal lock), the refusals. MuJoCo
// itself reads the rows in the mjcf.motion tests (tests/roundtrip/mjcf_check.cpp).
#include "writers/mjcf/mjcf_qpos.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/unit/test_asset.h"

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Eigen::Matrix3d xyz(const Eigen::Vector3d& a) {
  return rot(Eigen::Vector3d::UnitX(), a.x()) * rot(Eigen::Vector3d::UnitY(), a.y()) *
         rot(Eigen::Vector3d::UnitZ(), a.z());
}

// pelvis(0) <- left_hip(1) <- left_knee(3), pelvis <- spine1(2): MuJoCo's order 0, 1, 3, 2.
Asset smallAsset() {
  Eigen::MatrixXd world(4, 3);
  world << 0.0, 0.9, 0.0, 0.1, 0.8, 0.0, 0.0, 1.0, -0.02, 0.12, 0.45, 0.01;
  Asset a;
  a.skeleton =
      test::skeletonFromWorld({"pelvis", "left_hip", "spine1", "left_knee"}, {-1, 0, 0, 1}, world);
  AnimationClip clip;
  clip.name = "walk";
  clip.fps = 30.0;
  clip.times = {0.0, 1.0 / 30.0};
  clip.rotations.assign(4, RotationTrack(2, Eigen::Quaternionf::Identity()));
  clip.root_translation = {Eigen::Vector3d(0.1, 0.9, -0.2), Eigen::Vector3d(0.2, 1.0, 0.3)};
  a.animations.push_back(clip);
  return a;
}

TEST(MjcfQpos, HingeAnglesReproduceTheRotation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-kPi, kPi);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    Eigen::Vector3d want(u(rng), u(rng) / 2, u(rng));
    if (i % 4 == 0) want.y() = (i % 8 == 0 ? 1 : -1) * kPi / 2;  // gimbal lock
    if (i % 4 == 1) want.y() = kPi / 2 - 1e-9;                   // next to it
    const Eigen::Matrix3d r = xyz(want);
    const Eigen::Vector3d got = mjcfHingeAngles(r);
    EXPECT_LE(got.cwiseAbs().maxCoeff(), kPi) << got.transpose();
    worst = std::max(worst, (xyz(got) - r).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-12);
  // Away from gimbal lock the angles themselves come back.
  const Eigen::Vector3d a(0.3, -0.7, 2.5);
  EXPECT_LT((mjcfHingeAngles(xyz(a)) - a).norm(), 1e-12);
  // Not the z, y, x order: Rz(c) Ry(b) Rx(a) of the same angles is another rotation.
  const Eigen::Matrix3d zyx = rot(Eigen::Vector3d::UnitZ(), a.z()) *
                              rot(Eigen::Vector3d::UnitY(), a.y()) *
                              rot(Eigen::Vector3d::UnitX(), a.x());
  EXPECT_GT((mjcfHingeAngles(zyx) - a).norm(), 0.1);
}

TEST(MjcfQpos, RowsFollowMuJoCosOrderAndTheZUpTurn) {
  Asset a = smallAsset();
  AnimationClip& clip = a.animations.front();
  const double t = 0.4;
  // Frame 1: pelvis about the model's up axis (+Y), which is MuJoCo's +Z; left_hip about
  // model X (X stays X); left_knee about model Y (MuJoCo Z); spine1 about model Z (MuJoCo -Y).
  clip.rotations[0][1] = Eigen::Quaternionf(Eigen::AngleAxisf(float(t), Eigen::Vector3f::UnitY()));
  clip.rotations[1][1] = Eigen::Quaternionf(Eigen::AngleAxisf(float(t), Eigen::Vector3f::UnitX()));
  clip.rotations[3][1] = Eigen::Quaternionf(Eigen::AngleAxisf(float(t), Eigen::Vector3f::UnitY()));
  clip.rotations[2][1] = Eigen::Quaternionf(Eigen::AngleAxisf(float(t), Eigen::Vector3f::UnitZ()));
  Result<MjcfMotion> m = mjcfMotion(a, clip, "hinge");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->nq, 7 + 3 * 3);
  EXPECT_EQ(m->joint_names, (std::vector<std::string>{
                                "pelvis", "left_hip_x", "left_hip_y", "left_hip_z", "left_knee_x",
                                "left_knee_y", "left_knee_z", "spine1_x", "spine1_y", "spine1_z"}));
  ASSERT_EQ(m->qpos.size(), 2u * 16);
  const double* r0 = m->qpos.data();
  const double* r1 = r0 + 16;
  // Root position (x, y, z) -> (x, -z, y); identity quaternion with w first.
  const std::vector<double> first = {0.1, 0.2, 0.9, 1, 0, 0, 0};
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(r0[i], first[size_t(i)], 1e-12) << i;
  for (int i = 7; i < 16; ++i) EXPECT_EQ(r0[i], 0.0) << i;
  const std::vector<double> second = {
      0.2, -0.3, 1.0, std::cos(t / 2), 0, 0, std::sin(t / 2), t, 0, 0, 0, 0, t, 0, -t, 0};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(r1[i], second[size_t(i)], 1e-6) << i;  // float keys
}

TEST(MjcfQpos, BallJointsAndMissingTranslation) {
  Asset a = smallAsset();
  AnimationClip& clip = a.animations.front();
  clip.root_translation.clear();  // no translation: the rest position, as BVH
  clip.rotations[3][0] = Eigen::Quaternionf(-0.5f, 0.5f, 0.5f, 0.5f);  // w < 0 in the clip
  Result<MjcfMotion> m = mjcfMotion(a, clip, "ball");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->nq, 7 + 4 * 3);
  EXPECT_EQ(m->joint_names,
            (std::vector<std::string>{"pelvis", "left_hip", "left_knee", "spine1"}));
  EXPECT_NEAR(m->qpos[0], 0.0, 1e-12);
  EXPECT_NEAR(m->qpos[1], 0.0, 1e-12);
  EXPECT_NEAR(m->qpos[2], 0.9, 1e-12);
  // left_knee's quaternion (third body: qpos 11..14) turned Z up, w >= 0: the turn C maps
  // the axis (1, 1, 1) to (1, -1, 1), and the sign flips to w = 0.5.
  const std::vector<double> knee = {0.5, -0.5, 0.5, -0.5};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(m->qpos[size_t(11 + i)], knee[size_t(i)], 1e-6) << i;
}

TEST(MjcfQpos, RefusesATranslatedJoint) {
  Asset a = smallAsset();
  AnimationClip& clip = a.animations.front();
  clip.joint_translations.assign(4, {});
  for (int f = 0; f < 2; ++f)
    clip.joint_translations[1].push_back(a.skeleton.rest_local.row(1).transpose());
  EXPECT_TRUE(mjcfMotion(a, clip, "hinge").ok());  // at its rest offset: fine
  clip.joint_translations[1][1].y() += 0.01;
  EXPECT_EQ(mjcfMotion(a, clip, "hinge").message(),
            "MJCF writer: joint left_hip moves away from its rest offset (--root-bone, "
            "--dmpl-joints); MuJoCo's hinge and ball joints hold rotations only");
  clip.joint_translations.clear();
  clip.rotations[2].pop_back();
  EXPECT_NE(mjcfMotion(a, clip, "hinge").message().find("spine1 has 1 rotation keys, expected 2"),
            std::string::npos);
}

}  // namespace
}  // namespace smpl
