// validateAsset: a finished asset passes; one NaN, Inf or float-overflowing
// value in any serialised array fails with an error that names where it is.
#include "exporter/validate_asset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core/demo/demo_body.h"
#include "exporter/pipeline.h"

namespace smpl {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// The demo body with correctives and a two-frame animation clip, built once
// (the default export fits and refits; each case spoils its own copy).
Asset buildGoodAsset() {
  ExportOptions o;
  Result<Asset> a = buildAsset(demoBody(), o);
  EXPECT_TRUE(a.ok()) << a.message();
  AnimationClip clip;
  clip.name = "walk";
  clip.times = {0.0, 1.0 / 30};
  const size_t joints = a->skeleton.names.size();
  clip.rotations.assign(joints, RotationTrack(2, Eigen::Quaternionf::Identity()));
  clip.root_translation = {Eigen::Vector3d(0, 0.9, 0), Eigen::Vector3d(0.1, 0.9, 0)};
  clip.morph_weights =
      Eigen::MatrixXf::Zero(2, static_cast<Eigen::Index>(a->mesh.morph_targets.size()));
  a->animations.push_back(clip);
  return *a;
}
Asset goodAsset() {
  static const Asset built = buildGoodAsset();
  return built;
}

void expectError(const std::function<void(Asset*)>& spoil, const std::string& want) {
  Asset a = goodAsset();
  spoil(&a);
  Status st = validateAsset(a);
  ASSERT_FALSE(st.ok()) << "expected: " << want;
  EXPECT_EQ(st.message(), want);
}

TEST(ValidateAsset, FinishedAssetPasses) {
  const Asset a = goodAsset();
  ASSERT_FALSE(a.mesh.morph_targets.empty());
  Status st = validateAsset(a);
  EXPECT_TRUE(st.ok()) << st.message();
}

TEST(ValidateAsset, NamesTheMorphTargetAndVertex) {
  Asset a = goodAsset();
  const std::string name = a.mesh.morph_targets[3].name;
  expectError([](Asset* x) { x->mesh.morph_targets[3].deltas(12, 1) = static_cast<float>(kNan); },
              "morph target " + name + " vertex 12 is not finite (nan)");
}

TEST(ValidateAsset, EverySerialisedArrayIsChecked) {
  const Asset a = goodAsset();
  const std::string joint1 = a.skeleton.names[1];
  expectError([](Asset* x) { x->mesh.positions(5, 0) = static_cast<float>(kInf); },
              "mesh position of vertex 5 is not finite (inf)");
  expectError([](Asset* x) { x->mesh.normals(7, 2) = static_cast<float>(kNan); },
              "mesh normal of vertex 7 is not finite (nan)");
  expectError([](Asset* x) { x->mesh.weights(2, 0) = static_cast<float>(-kInf); },
              "skin weight of vertex 2 is not finite (-inf)");
  expectError([](Asset* x) { x->skeleton.rest_local(1, 1) = kNan; },
              "joint " + joint1 + " rest offset is not finite (nan)");
  expectError([](Asset* x) { x->skeleton.rest_world(1, 0) = 1e39; },
              "joint " + joint1 + " rest position exceeds the float32 range (1e+39)");
  expectError([](Asset* x) { x->animations[0].times[1] = kNan; },
              "animation walk key time of frame 1 is not finite (nan)");
  expectError([](Asset* x) { x->animations[0].rotations[4][1].x() = kNan; },
              "animation walk joint 4 frame 1 rotation is not finite (nan)");
  expectError([](Asset* x) { x->animations[0].root_translation[1].z() = 1e300; },
              "animation walk frame 1 root translation exceeds the float32 range (1e+300)");
  expectError([](Asset* x) { x->animations[0].morph_weights(1, 0) = static_cast<float>(kInf); },
              "animation walk morph weights of frame 1 is not finite (inf)");
  expectError([](Asset* x) { x->animations[0].fps = kNan; },
              "animation walk fps is not finite (nan)");
  expectError(
      [](Asset* x) {
        x->metadata.betas = {0.0, kNan};
      },
      "metadata betas 1 is not finite (nan)");
  expectError([](Asset* x) { x->metadata.expression = {kInf}; },
              "metadata expression 0 is not finite (inf)");
  expectError([](Asset* x) { x->mesh.morph_targets[0].rest_weight = static_cast<float>(kNan); },
              "morph target " + a.mesh.morph_targets[0].name + " rest weight is not finite (nan)");
  expectError([](Asset* x) { x->metadata.correctives[0].offset = kNan; },
              "metadata corrective " + a.metadata.correctives[0].target +
                  " scale/offset is not finite (nan)");
}

TEST(ValidateAsset, MetadataDoublesMayExceedFloat) {
  Asset a = goodAsset();
  a.metadata.betas = {1e300};  // written as JSON doubles, not float32
  EXPECT_TRUE(validateAsset(a).ok());
}

TEST(ValidateAsset, CorrectiveBasisIsChecked) {
  Asset a = goodAsset();
  a.metadata.corrective_basis.targets = {"pose_basis_0"};
  a.metadata.corrective_basis.projection = Eigen::MatrixXd::Zero(1, 3);
  a.metadata.corrective_basis.projection(0, 2) = kNan;
  a.metadata.corrective_basis.scale = {1.0};
  a.metadata.corrective_basis.offset = {0.0};
  Status st = validateAsset(a);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "metadata corrective basis matrix row 0 is not finite (nan)");
}

}  // namespace
}  // namespace smpl
