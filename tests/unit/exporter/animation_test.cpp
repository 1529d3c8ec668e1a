// Baking motions: layout mapping, resampling, Z-up conversion and per-frame
// corrective weights, checked against the forward pass's own definitions.
#include "exporter/animation.h"

#include <gtest/gtest.h>

#include "core/models/model_loader.h"
#include "exporter/pipeline.h"

namespace smpl {
namespace {

// Rotation keys are float (exporter/asset.h RotationTrack): a rotation matrix
// entry rounds by at most a few float ulps of 1.
constexpr double kKeyRounding = 5e-7;

const std::string kFixtures = std::string(SMPL_FIXTURE_DIR);

struct Loaded {
  BodyModel model;
  Asset asset;
  Motion motion;
};

Loaded load(const std::string& model, const std::string& motion) {
  Loaded l;
  Result<BodyModel> m = loadModel(kFixtures + "/models/" + model);
  EXPECT_TRUE(m.ok()) << m.message();
  l.model = *m;
  Result<Asset> a = buildAsset(l.model, ExportOptions());
  EXPECT_TRUE(a.ok()) << a.message();
  l.asset = *a;
  Result<Motion> mo = loadMotion(kFixtures + "/motions/" + motion);
  EXPECT_TRUE(mo.ok()) << mo.message();
  l.motion = *mo;
  return l;
}

TEST(Animation, SmplhMotionOnSmplDropsFingers) {
  Loaded l = load("smpl_small.npz", "amass_smplh.npz");
  Result<MotionMapping> map = mapMotion(l.model, l.motion, "walk.npz");
  ASSERT_TRUE(map.ok()) << map.message();
  EXPECT_EQ(map->dropped.size(), 30u);  // 2 x 15 finger joints
  EXPECT_EQ(map->missing, (std::vector<std::string>{"left_hand", "right_hand"}));
  EXPECT_EQ(map->source_of_joint[21], 21);
}

// Bones are matched by name, either SMPL-X eye spelling: a model whose joints
// still carry the old names (left_eye/right_eye) gets the eye rotations.
TEST(Animation, SmplxEyesMatchEitherSpelling) {
  Loaded l = load("smplx_small.npz", "amass_smplx.npz");
  ASSERT_EQ(l.model.joint_names[23], "left_eye_smplhf");
  l.model.joint_names[23] = "left_eye";
  l.model.joint_names[24] = "right_eye";
  Result<MotionMapping> map = mapMotion(l.model, l.motion, "walk.npz");
  ASSERT_TRUE(map.ok()) << map.message();
  EXPECT_EQ(map->source_of_joint[23], 23);
  EXPECT_EQ(map->source_of_joint[24], 24);
  EXPECT_TRUE(map->missing.empty());
  EXPECT_TRUE(map->dropped.empty());
}

TEST(Animation, ManoMotionCannotDriveSmpl) {
  Loaded l = load("mano_small.npz", "amass_smplh.npz");
  Result<MotionMapping> map = mapMotion(l.model, l.motion, "walk.npz");
  ASSERT_FALSE(map.ok());
  EXPECT_NE(map.message().find("walk.npz: a smplh motion cannot drive a mano model"),
            std::string::npos)
      << map.message();
}

TEST(Animation, ResampleZUpAndWeights) {
  Loaded l = load("smplh_small.npz", "amass_smplh.npz");
  AnimationOptions o;
  o.fps = 30;  // 120 -> 30: every 4th source frame, exactly
  Result<AnimationClip> clip = bakeAnimation(l.model, l.asset, l.motion, o, "walk.npz");
  ASSERT_TRUE(clip.ok()) << clip.message();
  ASSERT_EQ(clip->times.size(), 60u);  // frames 0, 4, ..., 236
  EXPECT_DOUBLE_EQ(clip->times[1], 1.0 / 30);
  const Eigen::Matrix3d up =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d j0 = l.asset.skeleton.rest_world.row(0).transpose();
  for (int i : {0, 17, 59}) {
    const Rotations& src = l.motion.frames[4 * i];
    EXPECT_LT(
        (clip->rotations[5][i].cast<double>().toRotationMatrix() - src[5]).cwiseAbs().maxCoeff(),
        kKeyRounding);
    EXPECT_LT((clip->rotations[0][i].cast<double>().toRotationMatrix() - up * src[0])
                  .cwiseAbs()
                  .maxCoeff(),
              kKeyRounding);
    EXPECT_LT((clip->root_translation[i] - up * (j0 + l.motion.translation[4 * i])).norm(), 1e-12);
    Eigen::VectorXd f = poseFeatures(src);
    for (int n : {0, 100, 450}) EXPECT_NEAR(clip->morph_weights(i, n), f[n], 1e-6);
  }
}

// With `release` the bake frees each decoded frame once no later output
// frame reads it: the clip is the same bit for bit (resampled, cut to a
// range), the frames it passed are empty, the others and the count stay.
TEST(Animation, ReleaseFreesPassedFramesAndBakesTheSameClip) {
  Loaded l = load("smplh_small.npz", "amass_smplh.npz");
  for (std::optional<double> fps : {std::optional<double>(30.0), std::optional<double>(50.0),
                                    std::optional<double>()}) {  // every 4th, slerped, every frame
    AnimationOptions o;
    o.fps = fps;
    o.first_frame = 3;
    o.end_frame = 90;
    Result<AnimationClip> kept = bakeAnimation(l.model, l.asset, l.motion, o, "m");
    Motion consumed = l.motion;
    Result<AnimationClip> freed =
        bakeAnimation(l.model, l.asset, consumed, o, "m", nullptr, &consumed);
    ASSERT_TRUE(kept.ok() && freed.ok()) << kept.message() << freed.message();
    ASSERT_EQ(consumed.frames.size(), l.motion.frames.size());
    for (size_t f = 0; f < consumed.frames.size(); ++f)
      EXPECT_EQ(consumed.frames[f].empty(), f >= 3 && f < 90) << fps.value_or(0) << " frame " << f;
    ASSERT_EQ(freed->rotations.size(), kept->rotations.size());
    for (size_t j = 0; j < kept->rotations.size(); ++j)
      for (size_t i = 0; i < kept->rotations[j].size(); ++i)
        ASSERT_EQ(freed->rotations[j][i].coeffs(), kept->rotations[j][i].coeffs()) << j << " " << i;
    EXPECT_EQ(freed->morph_weights, kept->morph_weights);
    EXPECT_EQ(freed->root_translation, kept->root_translation);
  }
  Motion other = l.motion;
  Result<AnimationClip> wrong =
      bakeAnimation(l.model, l.asset, l.motion, AnimationOptions(), "m", nullptr, &other);
  EXPECT_FALSE(wrong.ok());
}

// Rotation keys are stored as glTF writes them: unit in float, each key on
// the short path from the previous one (q and -q are the same rotation).
TEST(Animation, RotationKeysAreUnitAndContinuous) {
  Loaded l = load("smplh_small.npz", "amass_smplh.npz");
  for (size_t f = 0; f < l.motion.frames.size(); ++f)  // joint 1 spins: past pi, w changes sign
    l.motion.frames[f][1] =
        Eigen::AngleAxisd(0.3 * double(f), Eigen::Vector3d(0.2, 1, 0.1).normalized())
            .toRotationMatrix();
  Result<AnimationClip> clip = bakeAnimation(l.model, l.asset, l.motion, AnimationOptions(), "m");
  ASSERT_TRUE(clip.ok()) << clip.message();
  for (const RotationTrack& track : clip->rotations)
    for (size_t i = 0; i < track.size(); ++i) {
      EXPECT_NEAR(track[i].cast<double>().norm(), 1.0, 2e-7);
      if (i > 0) EXPECT_GE(track[i].dot(track[i - 1]), 0.0f) << i;
    }
}

TEST(Animation, SlerpBetweenFramesAndFrameRange) {
  Loaded l = load("smpl_small.npz", "smpl_72.npz");
  AnimationOptions o;
  o.fps = 60;  // 30 -> 60: odd frames halfway between source frames
  o.first_frame = 10;
  o.end_frame = 20;
  Result<AnimationClip> clip = bakeAnimation(l.model, l.asset, l.motion, o, "m.npz");
  ASSERT_TRUE(clip.ok()) << clip.message();
  ASSERT_EQ(clip->times.size(), 19u);
  Eigen::Quaterniond a(l.motion.frames[12][3]), b(l.motion.frames[13][3]);
  EXPECT_LT(clip->rotations[3][5].cast<double>().angularDistance(a.slerp(0.5, b)), kKeyRounding);
  EXPECT_EQ(l.motion.world, MotionWorld::Y);
  EXPECT_LT((clip->rotations[0][0].cast<double>().toRotationMatrix() - l.motion.frames[10][0])
                .cwiseAbs()
                .maxCoeff(),
            kKeyRounding);
  o.end_frame = 99;
  Result<AnimationClip> bad = bakeAnimation(l.model, l.asset, l.motion, o, "m.npz");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("outside the motion's 60 frames"), std::string::npos)
      << bad.message();
}

TEST(Animation, InPlaceKeepsHeightOnly) {
  Loaded l = load("smplh_small.npz", "amass_smplh.npz");
  AnimationOptions o;
  o.in_place = true;
  Result<AnimationClip> clip = bakeAnimation(l.model, l.asset, l.motion, o, "walk.npz");
  ASSERT_TRUE(clip.ok());
  const Eigen::Vector3d j0 = l.asset.skeleton.rest_world.row(0).transpose();
  EXPECT_DOUBLE_EQ(clip->root_translation[200].x(), j0.x());
  EXPECT_DOUBLE_EQ(clip->root_translation[200].z(), j0.z());
  const Eigen::Matrix3d up =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_NEAR(clip->root_translation[200].y(), (up * (j0 + l.motion.translation[200])).y(), 1e-12);
}

// A camera frame (OpenCV: y down, z forward) is turned upright by one half
// turn about x, about the world origin: --up -y, or the layout's default.
TEST(Animation, CameraFrameTurnsUprightByAHalfTurnAboutX) {
  Loaded l = load("smpl_small.npz", "smpl_72.npz");
  l.motion.world = MotionWorld::CameraYDown;
  const Eigen::Matrix3d half = Eigen::Vector3d(1, -1, -1).asDiagonal();
  const Eigen::Vector3d j0 = l.asset.skeleton.rest_world.row(0).transpose();
  for (UpAxis up : {UpAxis::Auto, UpAxis::NegY, UpAxis::Y}) {
    AnimationOptions o;
    o.up = up;
    Result<AnimationClip> clip = bakeAnimation(l.model, l.asset, l.motion, o, "m.npz");
    ASSERT_TRUE(clip.ok()) << clip.message();
    const Eigen::Matrix3d turn = up == UpAxis::Y ? Eigen::Matrix3d::Identity() : half;
    EXPECT_EQ(clip->source.world, up == UpAxis::Y ? "y" : "-y");
    for (int i : {0, 7, 29}) {
      const Rotations& src = l.motion.frames[i];
      EXPECT_LT((clip->rotations[0][i].cast<double>().toRotationMatrix() - turn * src[0])
                    .cwiseAbs()
                    .maxCoeff(),
                kKeyRounding);
      EXPECT_LT((clip->root_translation[i] - turn * (j0 + l.motion.translation[i])).norm(), 1e-12);
    }
  }
  EXPECT_LT((worldTurn(UpAxis::Auto, MotionWorld::Z) -
             Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix())
                .norm(),
            1e-15);
}

// A per-frame frame change (EasyMocap's Rh/Th) turns and moves the whole
// posed body about the world origin: root A R_0, root node A (J_0 + t) + b.
TEST(Animation, FrameChangeMovesTheBodyAboutTheOrigin) {
  Loaded l = load("smpl_small.npz", "smpl_72.npz");
  const size_t t = l.motion.frames.size();
  for (size_t f = 0; f < t; ++f) {
    l.motion.world_rotation.push_back(
        Eigen::AngleAxisd(0.05 * f, Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix());
    l.motion.world_translation.emplace_back(0.1 * f, 1.0, -2.0);
  }
  Result<AnimationClip> clip = bakeAnimation(l.model, l.asset, l.motion, AnimationOptions(), "m");
  ASSERT_TRUE(clip.ok()) << clip.message();
  const Eigen::Vector3d j0 = l.asset.skeleton.rest_world.row(0).transpose();
  for (int i : {0, 11, 29}) {
    const Eigen::Matrix3d& a = l.motion.world_rotation[i];
    EXPECT_LT((clip->rotations[0][i].cast<double>().toRotationMatrix() - a * l.motion.frames[i][0])
                  .cwiseAbs()
                  .maxCoeff(),
              kKeyRounding);
    EXPECT_LT((clip->root_translation[i] -
               (a * (j0 + l.motion.translation[i]) + l.motion.world_translation[i]))
                  .norm(),
              1e-12);
  }
}

}  // namespace
}  // namespace smpl
