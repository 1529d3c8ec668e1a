// --origin floor and --root-bone (exporter/placement.h): the lowest point
// against a brute-force playback of every vertex and frame (test_asset.h
// enginePlayback, no bound), the floor shift, and a root bone that leaves
// every posed vertex where it was.
#include "exporter/placement.h"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "core/models/model_loader.h"
#include "exporter/export_asset.h"
#include "exporter/metadata_json.h"
#include "tests/unit/test_asset.h"

namespace smpl {
namespace {

const std::string kFixtures = std::string(SMPL_FIXTURE_DIR);

double bruteLowest(const Asset& a) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const AnimationClip& c : a.animations)
    for (size_t t = 0; t < c.times.size(); ++t)
      lowest = std::min(lowest, test::enginePlayback(a, c, int(t)).col(1).minCoeff());
  return lowest;
}

struct Inputs {
  BodyModel model;
  Motion motion;
};

// The skin fit and the corrective refit are not what these tests are about:
// truncated weights and the model's posedirs are quicker.
ExportOptions truncated() {
  ExportOptions o;
  o.skin_weights = SkinWeightMethod::Truncated;
  o.corrective_refit = false;
  return o;
}

Inputs load() {
  Inputs in;
  Result<BodyModel> m = loadModel(kFixtures + "/models/smplh_small.npz");
  EXPECT_TRUE(m.ok()) << m.message();
  if (m) in.model = *m;
  Result<Motion> mo = loadMotion(kFixtures + "/motions/amass_smplh.npz");
  EXPECT_TRUE(mo.ok()) << mo.message();
  if (mo) in.motion = *mo;
  return in;
}

TEST(Placement, LowestPointIsTheBruteForceMinimum) {
  test::AssetSpec spec;
  spec.vertices = 40;
  spec.morph_targets = 6;
  spec.frames = 25;
  const Asset a = test::makeAsset(spec);
  EXPECT_NEAR(lowestPoint(a), bruteLowest(a), 1e-9);
  const Inputs in = load();
  Result<Asset> moving = exportAsset(in.model, truncated(), {{&in.motion, "walk", {}, nullptr}});
  ASSERT_TRUE(moving.ok()) << moving.message();
  EXPECT_NEAR(lowestPoint(*moving), bruteLowest(*moving), 1e-9);
}

TEST(Placement, LowestRestPointCountsDefaultWeights) {
  Asset a = test::makeAsset(test::AssetSpec());
  const double plain = a.mesh.positions.col(1).cast<double>().minCoeff();
  EXPECT_NEAR(lowestPoint(a), plain, 1e-9);
  a.mesh.morph_targets[0].deltas.col(1).setConstant(-0.5f);  // at weight 0.5: 0.25 lower
  a.mesh.morph_targets[0].rest_weight = 0.5f;
  EXPECT_NEAR(lowestPoint(a), plain - 0.25, 1e-6);
}

TEST(Placement, FloorPutsTheLowestPosedVertexAtZero) {
  const Inputs in = load();
  const std::vector<MotionInput> motions = {{&in.motion, "walk", {}, nullptr}};
  Result<Asset> model = exportAsset(in.model, truncated(), motions);
  ExportOptions floor = truncated();
  floor.origin = Origin::Floor;
  Result<Asset> placed = exportAsset(in.model, floor, motions);
  ASSERT_TRUE(model.ok() && placed.ok()) << placed.message();
  EXPECT_NEAR(bruteLowest(*placed), 0.0, 1e-6);
  const double dy = placed->placement.floor_offset;
  EXPECT_NEAR(dy, -bruteLowest(*model), 1e-9);
  EXPECT_EQ(placed->placement.origin, "floor");
  for (size_t t = 0; t < placed->animations[0].times.size(); t += 7) {  // shape unchanged
    const Eigen::MatrixXd a = test::enginePlayback(*model, model->animations[0], int(t));
    Eigen::MatrixXd b = test::enginePlayback(*placed, placed->animations[0], int(t));
    b.col(1).array() -= dy;
    EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6) << "frame " << t;
  }
  const nlohmann::json meta = nlohmann::json::parse(metadataJson(*placed));
  EXPECT_EQ(meta["origin"]["mode"], "floor");
  EXPECT_DOUBLE_EQ(meta["origin"]["offset"][1].get<double>(), dy);
  EXPECT_FALSE(nlohmann::json::parse(metadataJson(*model)).contains("origin"));
}

TEST(Placement, RootBoneKeepsEveryPosedVertex) {
  const Inputs in = load();
  const std::vector<MotionInput> motions = {{&in.motion, "walk", {}, nullptr}};
  ExportOptions floor = truncated();
  floor.origin = Origin::Floor;
  ExportOptions root = floor;
  root.root_bone = true;
  Result<Asset> plain = exportAsset(in.model, floor, motions);
  Result<Asset> rooted = exportAsset(in.model, root, motions);
  ASSERT_TRUE(plain.ok() && rooted.ok()) << rooted.message();
  const Skeleton& s = rooted->skeleton;
  const int k = in.model.numJoints();
  ASSERT_EQ(int(s.names.size()), k + 1);
  EXPECT_EQ(s.names[0], "root");
  EXPECT_EQ(s.names[1], "pelvis");
  EXPECT_EQ(s.parents[0], -1);
  EXPECT_EQ(s.parents[1], 0);
  for (int j = 1; j < k; ++j) EXPECT_EQ(s.parents[size_t(j) + 1], in.model.parents[size_t(j)] + 1);
  EXPECT_DOUBLE_EQ(s.rest_world(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(s.rest_world(0, 0), plain->skeleton.rest_world(0, 0));
  const AnimationClip& a = plain->animations[0];
  const AnimationClip& b = rooted->animations[0];
  for (size_t t = 0; t < a.times.size(); ++t) {
    const Eigen::Vector3d p = a.root_translation[t];  // the pelvis' world position
    EXPECT_EQ(b.root_translation[t], Eigen::Vector3d(p.x(), 0, p.z())) << t;
    EXPECT_EQ(b.joint_translations[1][t], Eigen::Vector3d(0, p.y(), 0)) << t;
    EXPECT_TRUE(b.rotations[0][t].isApprox(Eigen::Quaternionf::Identity()));
    EXPECT_TRUE(b.rotations[1][t].isApprox(a.rotations[0][t]));
    if (t % 7 != 0) continue;  // playback every 7th frame
    const Eigen::MatrixXd va = test::enginePlayback(*plain, a, int(t));
    const Eigen::MatrixXd vb = test::enginePlayback(*rooted, b, int(t));
    EXPECT_LT((va - vb).cwiseAbs().maxCoeff(), 1e-9) << "frame " << t;
  }
  EXPECT_EQ(rooted->mesh.morph_targets.size(), plain->mesh.morph_targets.size());
  EXPECT_EQ(rooted->metadata.correctives.size(), plain->metadata.correctives.size());
  // The metadata lists the model's joints only (runtimes index features by them).
  const nlohmann::json meta = nlohmann::json::parse(metadataJson(*rooted));
  EXPECT_EQ(meta["joint_names"], nlohmann::json(in.model.joint_names));
  EXPECT_EQ(meta["parents"], nlohmann::json(in.model.parents));
  EXPECT_EQ(meta["root_bone"]["name"], "root");
  EXPECT_EQ(meta["root_bone"]["child"], "pelvis");
}

TEST(Placement, StaticRootBoneStandsBelowThePelvis) {
  const Inputs in = load();
  ExportOptions root = truncated();
  root.root_bone = true;  // exportAsset does not imply floor; the request does
  root.origin = Origin::Floor;
  Result<Asset> a = exportAsset(in.model, root, {});
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_NEAR(a->mesh.positions.col(1).minCoeff(), 0.0f, 1e-6f);
  const Skeleton& s = a->skeleton;
  EXPECT_EQ(s.rest_local.row(0), Eigen::RowVector3d(s.rest_world(1, 0), 0, s.rest_world(1, 2)));
  EXPECT_EQ(s.rest_local.row(1), Eigen::RowVector3d(0, s.rest_world(1, 1), 0));
  EXPECT_GE(a->mesh.joints.minCoeff(), 1);  // model joint k is file joint k + 1; root has no weight
}

}  // namespace
}  // namespace smpl
