// measurePruningError (exporter/pruning_error.h) runs the batched forward
// pass in float; its numbers must match the double-precision reference
// forward() (core/math/forward.h) evaluated pose by pose, here recomputed
// independently on the same held-out poses.
#include "exporter/pruning_error.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/demo/demo_body.h"
#include "core/math/corrective_refit.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"
#include "core/models/model_loader.h"
#include "exporter/export_skin.h"

namespace smpl {
namespace {

// Mean and max vertex distance, all weights vs `weights` (posed with the
// correctives of `pruned_model`: the model, or a copy with refitted
// posedirs), by forward().
SkinError referenceError(const BodyModel& model, const ExportOptions& o,
                         const Eigen::MatrixXd& weights, int poses,
                         const BodyModel* pruned_model = nullptr) {
  ForwardInput in;
  in.betas = Eigen::Map<const Eigen::VectorXd>(o.betas.data(), Eigen::Index(o.betas.size()));
  SkinError e;
  double sum = 0.0;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), poses, 20261124)) {
    in.rotations = rotationsFromAxisAngle(pose);
    in.weights = nullptr;
    const Eigen::MatrixXd full = forward(model, in)->vertices;
    in.weights = &weights;
    const Eigen::VectorXd d =
        (full - forward(pruned_model ? *pruned_model : model, in)->vertices).rowwise().norm();
    sum += d.sum();
    e.max_m = std::max(e.max_m, d.maxCoeff());
  }
  e.mean_m = sum / (double(poses) * model.numVertices());
  return e;
}

void expectClose(const SkinError& got, const SkinError& want, const char* what) {
  EXPECT_GT(want.mean_m, 0.0) << what;
  EXPECT_NEAR(got.mean_m, want.mean_m, 1e-3 * want.mean_m) << what;
  EXPECT_NEAR(got.max_m, want.max_m, 1e-3 * want.max_m) << what;
}

void checkModel(const BodyModel& model, const std::vector<double>& betas) {
  const int poses = 32;
  ExportOptions o;
  o.betas = betas;
  o.max_influences = 3;
  o.skin_weights = SkinWeightMethod::Optimized;
  Result<ShapedBody> body =
      shapeBody(model, Eigen::Map<const Eigen::VectorXd>(betas.data(), Eigen::Index(betas.size())));
  ASSERT_TRUE(body.ok()) << body.message();
  const SparseSkin fitted = exportSkin(model, *body, o);
  const CorrectiveRefit refit = refitCorrectives(model, *body, fitted, CorrectiveRefitOptions());
  ASSERT_FALSE(refit.empty());
  Result<PruningError> e = measurePruningError(model, o, poses, &fitted, &refit);
  ASSERT_TRUE(e.ok()) << e.message();
  EXPECT_EQ(e->poses, poses);
  EXPECT_EQ(e->influences, 3);
  const Eigen::MatrixXd truncated = denseWeights(pruneWeights(model.weights, 3), model.numJoints());
  expectClose(e->truncated, referenceError(model, o, truncated, poses), "truncated");
  const Eigen::MatrixXd dense = denseWeights(fitted, model.numJoints());
  EXPECT_TRUE(e->refit);
  expectClose(e->without_refit, referenceError(model, o, dense, poses), "fitted");
  BodyModel refitted = model;  // the posedirs the export writes
  refitted.posedirs = refit.posedirs(model);
  expectClose(SkinError{e->mean_m, e->max_m}, referenceError(model, o, dense, poses, &refitted),
              "fitted + refit");
  EXPECT_LT(e->mean_m, e->without_refit.mean_m);
}

TEST(PruningError, MatchesTheReferenceForwardPassOnTheBuiltinBody) {
  checkModel(demoBody(), {0.5, -1.0});
}

TEST(PruningError, MatchesTheReferenceForwardPassOnTheSmplFixture) {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  checkModel(*model, {});
}

}  // namespace
}  // namespace smpl
