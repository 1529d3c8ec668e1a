// The asset the pipeline builds honours docs/file-contract.md: rest mesh v_shaped, local
// rest translations J_k - J_p(k), one morph target per posedirs column named
// pose_<joint>_<r><c>, pruned weights, metadata.
#include "exporter/pipeline.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/math/forward.h"
#include "core/models/model_loader.h"

namespace smpl {
namespace {

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

TEST(Pipeline, AssetMatchesModel) {
  Result<BodyModel> model = loadModel(kModels + "smpl_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  ExportOptions o;
  o.betas = {0.5, -1.0};
  o.shape_keys = 2;
  Result<Asset> asset = buildAsset(*model, o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  Eigen::VectorXd betas(2);
  betas << 0.5, -1.0;
  Result<ShapedBody> body = shapeBody(*model, betas);
  ASSERT_TRUE(body.ok());
  const SkinnedMesh& mesh = asset->mesh;
  EXPECT_LT((mesh.positions.cast<double>() - body->v_shaped).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_EQ(asset->skeleton.rest_local.row(4),
            body->joints.row(4) - body->joints.row(1));  // left_knee under left_hip
  ASSERT_EQ(mesh.morph_targets.size(), 207u + 2u);
  EXPECT_EQ(mesh.morph_targets[0].name, "pose_left_hip_00");
  EXPECT_EQ(mesh.morph_targets[9 * 3 + 5].name, "pose_left_knee_12");
  EXPECT_EQ(mesh.morph_targets[206].name, "pose_right_hand_22");
  EXPECT_EQ(mesh.morph_targets[207].name, "shape_0");
  // The deltas are posedirs, refitted at the vertices whose influences were
  // cut (--corrective-refit, on by default; core/math/corrective_refit.h).
  ASSERT_FALSE(asset->corrective_refit->empty());
  for (int n : {0, 50, 206})
    for (int i = 0; i < model->numVertices(); i += 37)
      for (int c = 0; c < 3; ++c)
        EXPECT_FLOAT_EQ(mesh.morph_targets[n].deltas(i, c),
                        static_cast<float>(asset->corrective_refit->delta(*model, 3 * i + c, n)));
  EXPECT_EQ(mesh.joints.cols(), 4);
  for (int i = 0; i < mesh.weights.rows(); ++i) EXPECT_NEAR(mesh.weights.row(i).sum(), 1.0f, 1e-6f);
  EXPECT_EQ(asset->metadata.correctives.size(), 207u);
  EXPECT_EQ(asset->metadata.correctives[31].feature, 31);
  EXPECT_EQ(asset->metadata.betas.size(), 10u);
  EXPECT_EQ(asset->metadata.model_kind, "smpl");
}

TEST(Pipeline, CorrectiveRefitChangesOnlyTheDeltasOfCutVertices) {
  Result<BodyModel> model = loadModel(kModels + "smpl_small.npz");
  ASSERT_TRUE(model.ok());
  ExportOptions o;
  o.corrective_refit = false;
  Result<Asset> plain = buildAsset(*model, o);
  o.corrective_refit = true;
  Result<Asset> refit = buildAsset(*model, o);
  ASSERT_TRUE(plain.ok() && refit.ok());
  EXPECT_TRUE(plain->corrective_refit->empty());
  ASSERT_FALSE(refit->corrective_refit->empty());
  int changed = 0;
  for (int n = 0; n < model->numPoseFeatures(); ++n)
    for (int i = 0; i < model->numVertices(); ++i) {
      const bool cut = (model->weights.row(i).array() > 0).count() > 4;
      for (int c = 0; c < 3; ++c) {
        const float p = static_cast<float>(model->posedirs(3 * i + c, n));
        EXPECT_EQ(plain->mesh.morph_targets[size_t(n)].deltas(i, c), p);
        const float r = refit->mesh.morph_targets[size_t(n)].deltas(i, c);
        if (!cut) EXPECT_EQ(r, p) << "vertex " << i;
        changed += r != p;
      }
    }
  EXPECT_GT(changed, 0);
  EXPECT_TRUE(plain->mesh.weights == refit->mesh.weights);
  EXPECT_TRUE(plain->mesh.positions == refit->mesh.positions);
}

TEST(Pipeline, RejectsTooManyBetas) {
  Result<BodyModel> model = loadModel(kModels + "smpl_small.npz");
  ASSERT_TRUE(model.ok());
  ExportOptions o;
  o.betas.assign(11, 0.0);
  Result<Asset> asset = buildAsset(*model, o);
  ASSERT_FALSE(asset.ok());
  EXPECT_NE(asset.message().find("11 values given"), std::string::npos) << asset.message();
}

TEST(Pipeline, UvSeamsSplitVerticesAndTargetsFollow) {
  Result<BodyModel> model = loadModel(kModels + "smpl_small.npz");
  ASSERT_TRUE(model.ok());
  // Every face gets its own three UVs: every corner becomes a distinct vertex.
  const std::string path = testing::TempDir() + "uv.obj";
  {
    std::ofstream obj(path);
    for (int i = 0; i < model->numVertices(); ++i) obj << "v 0 0 0\n";
    for (int f = 0; f < model->faces.rows(); ++f) obj << "vt 0 0\nvt 1 0\nvt 0 1\n";
    for (int f = 0; f < model->faces.rows(); ++f)
      obj << "f " << model->faces(f, 0) + 1 << "/" << 3 * f + 1 << " " << model->faces(f, 1) + 1
          << "/" << 3 * f + 2 << " " << model->faces(f, 2) + 1 << "/" << 3 * f + 3 << "\n";
  }
  ExportOptions o;
  o.uv_obj = path;
  Result<Asset> asset = buildAsset(*model, o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  const SkinnedMesh& mesh = asset->mesh;
  EXPECT_EQ(mesh.positions.rows(), 3 * model->faces.rows());
  EXPECT_EQ(mesh.uvs.rows(), mesh.positions.rows());
  for (int i = 0; i < mesh.positions.rows(); i += 11) {
    const int s = mesh.source_vertex[i];
    EXPECT_FLOAT_EQ(mesh.morph_targets[3].deltas(i, 1),
                    static_cast<float>(asset->corrective_refit->delta(*model, 3 * s + 1, 3)));
    EXPECT_FLOAT_EQ(mesh.positions(i, 0), static_cast<float>(model->v_template(s, 0)));
  }
  std::ofstream(path) << "v 0 0 0\nvt 0 0\nf 1/1 2/1 3/1\n";
  Result<Asset> bad = buildAsset(*model, o);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("uv.obj: has 1 vertices"), std::string::npos) << bad.message();
}

}  // namespace
}  // namespace smpl
