// --rest-pose a (exporter/rest_pose.h): the offsets move to the A pose and
// the re-expressed keys put every joint where the T-rest keys put it. Blender
// reads the BVH the same way in the bvh.blender.*_resta tests.
#include "exporter/rest_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../test_asset.h"

namespace smpl {
namespace {

// pelvis, spine, left_shoulder, left_elbow, right_shoulder, right_elbow:
// skeleton only, `frames` random local rotations and root positions.
Asset arms(int frames) {
  Eigen::MatrixXd world(6, 3);
  world << 0, 1, 0, 0, 1.3, 0, 0.2, 1.45, 0, 0.45, 1.44, 0.01, -0.2, 1.45, 0, -0.45, 1.46, 0.02;
  Asset a;
  a.skeleton = test::skeletonFromWorld(
      {"pelvis", "spine", "left_shoulder", "left_elbow", "right_shoulder", "right_elbow"},
      {-1, 0, 1, 2, 1, 4}, world);
  a.skeleton_only = true;
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  AnimationClip clip;
  clip.name = "walk";
  for (int t = 0; t < frames; ++t) clip.times.push_back(t / 30.0);
  clip.rotations.resize(6);
  for (auto& track : clip.rotations)
    for (int t = 0; t < frames; ++t)
      track.push_back(
          Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().cast<float>());
  for (int t = 0; t < frames; ++t) clip.root_translation.emplace_back(n(rng), n(rng), n(rng));
  a.animations.push_back(clip);
  return a;
}

// World joint positions of frame f: root translation, then rest offsets
// rotated by the parents' world rotations.
Eigen::MatrixXd worldJoints(const Asset& a, int f) {
  const Skeleton& s = a.skeleton;
  const AnimationClip& c = a.animations[0];
  std::vector<Eigen::Quaterniond> rot(s.names.size());
  Eigen::MatrixXd p(Eigen::Index(s.names.size()), 3);
  for (size_t k = 0; k < s.names.size(); ++k) {
    const Eigen::Quaterniond local = c.rotations[k][size_t(f)].cast<double>();
    const int q = s.parents[k];
    if (q < 0) {
      rot[k] = local;
      p.row(Eigen::Index(k)) = c.root_translation[size_t(f)].transpose();
    } else {
      rot[k] = rot[size_t(q)] * local;
      p.row(Eigen::Index(k)) =
          p.row(q) + (rot[size_t(q)] * s.rest_local.row(Eigen::Index(k)).transpose()).transpose();
    }
  }
  return p;
}

TEST(RestPose, TheARestMovesTheArmsAndKeepsEveryPosedJoint) {
  const Asset t = arms(4);
  Asset a = t;
  ASSERT_TRUE(applyARestPose(&a).ok());
  EXPECT_EQ(a.metadata.rest_pose, "a");
  // the left elbow's offset turned 45 degrees down about z, the spine's unchanged
  const Eigen::Vector3d bone = t.skeleton.rest_local.row(3).transpose();
  const Eigen::Vector3d down = Eigen::AngleAxisd(-M_PI / 4, Eigen::Vector3d::UnitZ()) * bone;
  EXPECT_LT((a.skeleton.rest_local.row(3).transpose() - down).norm(), 1e-12);
  EXPECT_LT(
      (a.skeleton.rest_world.row(3) - (a.skeleton.rest_world.row(2) + down.transpose())).norm(),
      1e-12);
  EXPECT_EQ(a.skeleton.rest_local.row(1), t.skeleton.rest_local.row(1));
  for (int f = 0; f < 4; ++f) {
    const double moved = (worldJoints(a, f) - worldJoints(t, f)).cwiseAbs().maxCoeff();
    EXPECT_LT(moved, 1e-6) << "frame " << f;
    // the A offsets with the T keys (not re-expressed) put the arms elsewhere
    Asset offsets_only = a;
    offsets_only.animations = t.animations;
    EXPECT_GT((worldJoints(offsets_only, f) - worldJoints(t, f)).cwiseAbs().maxCoeff(), 1e-2);
  }
}

TEST(RestPose, IdentityKeysBecomeTheInverseOfTheAPose) {
  Asset a = arms(1);
  for (auto& track : a.animations[0].rotations) track[0] = Eigen::Quaternionf::Identity();
  ASSERT_TRUE(applyARestPose(&a).ok());
  const Eigen::Quaternionf up(Eigen::AngleAxisf(float(M_PI / 4), Eigen::Vector3f::UnitZ()));
  EXPECT_TRUE(a.animations[0].rotations[2][0].isApprox(up, 1e-6f));  // left_shoulder: +45 back
  EXPECT_TRUE(a.animations[0].rotations[3][0].isApprox(Eigen::Quaternionf::Identity(), 1e-6f));
}

TEST(RestPose, RefusesAHandAndAMesh) {
  Asset hand = arms(1);
  hand.skeleton.names[2] = "index1";
  EXPECT_NE(applyARestPose(&hand).message().find("no left_shoulder and right_shoulder"),
            std::string::npos);
  Asset mesh = arms(1);
  mesh.skeleton_only = false;
  EXPECT_NE(applyARestPose(&mesh).message().find("only a skeleton without a mesh"),
            std::string::npos);
}

}  // namespace
}  // namespace smpl
