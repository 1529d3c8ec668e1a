// Fitted skin weights (core/math/skin_weight_fit.h): the simplex QP against a
// known solution and a brute-force search, the fit's held-out error against
// truncation (exporter/pruning_error.h: poses the fit never trains on), and
// the layout contract (non-negative, sum 1, at most M, thread-independent).
#include "core/math/skin_weight_fit.h"

#include <gtest/gtest.h>

#include "core/demo/demo_body.h"
#include "core/models/model_loader.h"
#include "exporter/export_skin.h"
#include "exporter/pruning_error.h"

namespace smpl {
namespace {

TEST(SolveSimplexQp, ProjectsOntoTheSimplex) {
  // min |u - t|^2 on the simplex, t = (1.5, -0.5, 0.2): the projection is (1, 0, 0).
  const Eigen::Vector3d t(1.5, -0.5, 0.2);
  const Eigen::VectorXd u = solveSimplexQp(2.0 * Eigen::Matrix3d::Identity(), 2.0 * t,
                                           Eigen::Vector3d::Constant(1.0 / 3));
  EXPECT_NEAR(u(0), 1.0, 1e-12);
  EXPECT_NEAR(u(1), 0.0, 1e-12);
  EXPECT_NEAR(u(2), 0.0, 1e-12);
  // t = (0.6, 0.5, -1): both positive entries shift by 0.05 -> (0.55, 0.45, 0).
  const Eigen::VectorXd v =
      solveSimplexQp(2.0 * Eigen::Matrix3d::Identity(), 2.0 * Eigen::Vector3d(0.6, 0.5, -1.0),
                     Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR(v(0), 0.55, 1e-12);
  EXPECT_NEAR(v(1), 0.45, 1e-12);
  EXPECT_NEAR(v(2), 0.0, 1e-12);
}

TEST(SolveSimplexQp, NoGridPointIsBetter) {
  for (int seed = 1; seed <= 20; ++seed) {
    std::srand(unsigned(seed));
    const Eigen::Matrix3d a = Eigen::Matrix3d::Random();
    const Eigen::Matrix3d h = a * a.transpose() + 1e-3 * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d c = Eigen::Vector3d::Random();
    auto objective = [&](const Eigen::Vector3d& u) { return 0.5 * u.dot(h * u) - c.dot(u); };
    const Eigen::VectorXd u = solveSimplexQp(h, c, Eigen::Vector3d(1, 0, 0));
    EXPECT_GE(u.minCoeff(), 0.0);
    EXPECT_NEAR(u.sum(), 1.0, 1e-12);
    const int steps = 200;
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) {
        const Eigen::Vector3d g(double(i) / steps, double(j) / steps,
                                double(steps - i - j) / steps);
        EXPECT_LE(objective(u), objective(g) + 1e-12) << "seed " << seed;
      }
  }
}

struct Errors {
  SkinError truncated, fitted;
};

// Truncated and fitted weights alone (model's correctives; the refit:
// corrective_refit_test) on 32 held-out motion-like poses, the distribution
// the fit trains on (core/math/motion_poses.h, other seed).
Errors heldOut(const BodyModel& model, int m) {
  ExportOptions o;
  o.max_influences = m;
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  const std::vector<Rotations> frames = heldOutFrames(model, 32, /*motion_like=*/true);
  Result<SkinError> t = measureSkinOn(model, o, pruneWeights(model.weights, m), nullptr, frames);
  Result<SkinError> f = measureSkinOn(model, o, exportSkin(model, body, o), nullptr, frames);
  EXPECT_TRUE(t.ok() && f.ok());
  return {*t, *f};
}

// The goal is 30% below truncation; every M-subset of the fixture's
// at most 6 influences (exhaustive support) brings it to 72% on motion-like
// poses (smpl-skin-report; 28% on uniform random poses, which it no longer
// trains on).
TEST(FitSkinWeights, HeldOutErrorOnTheSmplFixtureIsWellBelowTruncation) {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  const Errors e = heldOut(*model, 4);
  EXPECT_LE(e.fitted.mean_m, 0.58 * e.truncated.mean_m)
      << e.fitted.mean_m << " vs " << e.truncated.mean_m;
  EXPECT_LE(e.fitted.max_m, e.truncated.max_m) << e.fitted.max_m << " vs " << e.truncated.max_m;
}

// The built-in body cannot reach the 30% goal: no weights on 4 of a
// vertex's joints do better than 15% on these very poses (see the next
// test). The fit gains 11% and, pulled toward the truncated weights, does
// not raise the worst vertex (without the pull: 2.44 mm against 2.35 mm).
// Motion-like held-out poses: 36% below truncation in the mean, 63% at the
// maximum (smpl-skin-report). On uniform random poses the weights alone are
// 18% worse (the refit, on by default, brings the export 65% below there).
TEST(FitSkinWeights, HeldOutMeanErrorOfTheBuiltinBodyIsBelowTruncation) {
  const Errors e = heldOut(demoBody(), 4);
  EXPECT_LE(e.fitted.mean_m, 0.8 * e.truncated.mean_m)
      << e.fitted.mean_m << " vs " << e.truncated.mean_m;
  EXPECT_LE(e.fitted.max_m, e.truncated.max_m) << e.fitted.max_m << " vs " << e.truncated.max_m;
}

// The fit trained on the held-out poses themselves (summed distance
// minimised, no prior, no guard; smpl-skin-report's "bound") is at least as
// good there as the fit trained elsewhere, and still misses 30% on the
// built-in body: the goal is out of reach for any weights, not for the fit.
TEST(FitSkinWeights, FitOnTheHeldOutPosesBoundsTheBuiltinBodysGain) {
  const BodyModel& model = demoBody();
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  SkinFitOptions o;
  o.training_poses = 32;
  o.seed = 20261124;      // exporter/pruning_error.h's held-out poses
  o.motion_like = false;  // those poses are uniform random
  o.prior_strength = 0.0;
  o.guard = false;
  o.l1_iterations = 30;
  auto heldOutError = [&] {
    return measureSkinError(model, ExportOptions(),
                            denseWeights(fitSkinWeights(model, *body, o), model.numJoints()), 32);
  };
  Result<SkinError> bound = heldOutError();
  ASSERT_TRUE(bound.ok()) << bound.message();
  ExportOptions four;  // the export's fit and truncation on the same (uniform) poses
  const Errors e{
      *measureSkinError(model, four,
                        denseWeights(pruneWeights(model.weights, 4), model.numJoints()), 32),
      *measureSkinError(model, four,
                        denseWeights(exportSkin(model, *body, four), model.numJoints()), 32)};
  EXPECT_LT(bound->mean_m, e.fitted.mean_m);
  EXPECT_GT(bound->mean_m, 0.7 * e.truncated.mean_m)
      << bound->mean_m << " vs " << e.truncated.mean_m;
  // Least squares only (no reweighting): a larger summed distance.
  o.l1_iterations = 0;
  Result<SkinError> squares = heldOutError();
  ASSERT_TRUE(squares.ok());
  EXPECT_LT(bound->mean_m, squares->mean_m);
}

TEST(FitSkinWeights, RowsAreConvexCombinationsAndThreadIndependent) {
  const BodyModel& model = demoBody();
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  SkinFitOptions o;
  o.max_influences = 3;
  o.threads = 1;
  const SparseSkin one = fitSkinWeights(model, *body, o);
  o.threads = 3;
  const SparseSkin three = fitSkinWeights(model, *body, o);
  ASSERT_EQ(one.weights.cols(), 3);
  EXPECT_TRUE(one.weights == three.weights && one.joints == three.joints);
  EXPECT_GE(one.weights.minCoeff(), 0.0);
  EXPECT_LE((one.weights.rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-12);
  for (Eigen::Index i = 0; i < one.weights.rows(); ++i)
    for (Eigen::Index s = 1; s < 3; ++s) EXPECT_LE(one.weights(i, s), one.weights(i, s - 1));
}

TEST(FitSkinWeights, VerticesWithAtMostMInfluencesKeepTheirWeights) {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  Result<ShapedBody> body = shapeBody(*model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  SkinFitOptions o;
  o.max_influences = 8;  // the fixture has at most 6 influences per vertex
  const Eigen::MatrixXd dense = denseWeights(fitSkinWeights(*model, *body, o), model->numJoints());
  EXPECT_LE((dense - model->weights).cwiseAbs().maxCoeff(), 1e-12);
}

// The prior is the model's weights on the chosen support, renormalised to
// sum 1 (the header): with an overwhelming prior_strength the fit returns it,
// whatever support it picked. Unnormalised, the simplex constraint would
// shift every weight by the same amount instead (the Euclidean projection),
// which differs wherever the support's weights are unequal.
TEST(FitSkinWeights, AnOverwhelmingPriorGivesTheRenormalisedModelWeights) {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  Result<ShapedBody> body = shapeBody(*model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  SkinFitOptions o;
  o.max_influences = 2;
  o.training_poses = 8;
  o.prior_strength = 1e9;
  const SparseSkin fit = fitSkinWeights(*model, *body, o);
  int cut = 0;
  for (Eigen::Index i = 0; i < fit.weights.rows(); ++i) {
    double kept = 0;
    for (Eigen::Index s = 0; s < 2; ++s) kept += model->weights(i, fit.joints(i, s));
    if (fit.weights(i, 1) == 0.0 || kept > 1.0 - 1e-9) continue;  // nothing was cut
    ++cut;
    for (Eigen::Index s = 0; s < 2; ++s)
      ASSERT_NEAR(fit.weights(i, s), model->weights(i, fit.joints(i, s)) / kept, 1e-6)
          << "vertex " << i << " slot " << s;
  }
  EXPECT_GT(cut, 100);  // the fixture's vertices with more than 2 influences
}

TEST(ExportSkin, AllInfluencesIsEveryJoint) {
  ExportOptions o;
  o.max_influences = kAllInfluences;
  EXPECT_EQ(influencesFor(demoBody(), o), demoBody().numJoints());
  o.max_influences = 6;
  EXPECT_EQ(influencesFor(demoBody(), o), 6);
}

}  // namespace
}  // namespace smpl
