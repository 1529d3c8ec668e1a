// refitCorrectives (core/math/corrective_refit.h): the refitted deltas must
// bring the pruned skin closer to the unpruned model on poses the refit never
// saw, measured by the double-precision forward() (core/math/forward.h) of a
// model copy that carries the refitted posedirs; vertices whose influences
// were not cut keep the model's deltas; the guard keeps them where the refit
// is worse; the result does not depend on the thread count.
#include "core/math/corrective_refit.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/demo/demo_body.h"
#include "core/math/forward.h"
#include "core/math/motion_poses.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weight_fit.h"
#include "core/math/skin_weights.h"
#include "core/models/model_loader.h"

namespace smpl {
namespace {

struct Error {
  double mean = 0.0, max = 0.0;
};

// All weights (model) vs `skin` posed with the correctives of `posed_with`, by forward().
Error errorOf(const BodyModel& model, const BodyModel& posed_with, const SparseSkin& skin,
              const std::vector<Eigen::VectorXd>& poses) {
  const Eigen::MatrixXd weights = denseWeights(skin, model.numJoints());
  Error e;
  for (const Eigen::VectorXd& pose : poses) {
    ForwardInput in;
    in.rotations = rotationsFromAxisAngle(pose);
    const Eigen::MatrixXd full = forward(model, in)->vertices;
    in.weights = &weights;
    const Eigen::VectorXd d = (full - forward(posed_with, in)->vertices).rowwise().norm();
    e.mean += d.sum() / (double(poses.size()) * double(d.size()));
    e.max = std::max(e.max, d.maxCoeff());
  }
  return e;
}

BodyModel withRefit(const BodyModel& model, const CorrectiveRefit& refit) {
  BodyModel copy = model;
  copy.posedirs = refit.posedirs(model);
  return copy;
}

BodyModel smplFixture() {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  EXPECT_TRUE(model.ok()) << model.message();
  return model.ok() ? *model : demoBody();
}

// Held-out sets the refit never trains or validates on.
std::vector<std::vector<Eigen::VectorXd>> heldOut(const BodyModel& model) {
  return {samplePoses(model.numJoints(), 24, 777), sampleMotionPoses(model.joint_names, 24, 778)};
}

void expectRefitHelps(const BodyModel& model, const SparseSkin& skin, double mean_gain,
                      double max_gain) {
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  const CorrectiveRefit refit = refitCorrectives(model, body, skin, CorrectiveRefitOptions());
  ASSERT_GT(refit.cut, 0);
  ASSERT_FALSE(refit.empty());
  const BodyModel refitted = withRefit(model, refit);
  for (const std::vector<Eigen::VectorXd>& poses : heldOut(model)) {
    const Error before = errorOf(model, model, skin, poses);
    const Error after = errorOf(model, refitted, skin, poses);
    EXPECT_LT(after.mean, (1.0 - mean_gain) * before.mean) << model.name;
    EXPECT_LE(after.max, (1.0 - max_gain) * before.max) << model.name;
  }
}

TEST(CorrectiveRefit, HalvesTheTruncationErrorOnHeldOutPosesOfTheBuiltinBody) {
  const BodyModel& model = demoBody();
  expectRefitHelps(model, pruneWeights(model.weights, 4), 0.5, 0.4);
}

TEST(CorrectiveRefit, LowersTheFittedSkinsErrorOnTheSmplFixture) {
  const BodyModel model = smplFixture();
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  SkinFitOptions fit;
  fit.max_influences = 2;
  // The fixture's random skeleton moves vertices by topologically distant
  // joints: the features of the vertex's joints and their parents explain
  // less of the error than on a body (smpl-skin-report: 10-40% there).
  expectRefitHelps(model, fitSkinWeights(model, body, fit), 0.05, 0.0);
}

TEST(CorrectiveRefit, KeepsTheModelsDeltasWhereNoInfluenceWasCut) {
  const BodyModel& model = demoBody();  // most of its vertices have at most 4 influences
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  const SparseSkin skin = pruneWeights(model.weights, 4);
  const CorrectiveRefit refit = refitCorrectives(model, body, skin, CorrectiveRefitOptions());
  ASSERT_EQ(refit.block.size(), size_t(model.numVertices()));
  int uncut = 0;
  for (Eigen::Index i = 0; i < model.numVertices(); ++i) {
    const bool cut = (model.weights.row(i).array() > 0).count() > 4;
    if (!cut) {
      ++uncut;
      EXPECT_EQ(refit.block[size_t(i)], -1) << "vertex " << i;
      EXPECT_EQ(refit.delta(model, 3 * i + 1, 5), model.posedirs(3 * i + 1, 5));
    }
  }
  EXPECT_GT(uncut, 0);
  // Every vertex has all-influences skin: nothing to refit.
  const CorrectiveRefit none = refitCorrectives(
      model, body, pruneWeights(model.weights, model.numJoints()), CorrectiveRefitOptions());
  EXPECT_EQ(none.cut, 0);
  EXPECT_TRUE(none.empty());
}

TEST(CorrectiveRefit, GuardKeepsTheModelsDeltasWhereTheRefitIsWorse) {
  // Four training poses and no ridge: the refit overfits, the guard must
  // leave such vertices alone, so held-out errors are never above the
  // model's deltas and are lower than the unguarded refit's.
  const BodyModel model = smplFixture();
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  const SparseSkin skin = pruneWeights(model.weights, 2);
  CorrectiveRefitOptions o;
  o.training_poses = 4;
  o.ridge = 1e-9;
  const CorrectiveRefit guarded = refitCorrectives(model, body, skin, o);
  o.guard = false;
  const CorrectiveRefit unguarded = refitCorrectives(model, body, skin, o);
  EXPECT_GT(guarded.kept, 0);
  EXPECT_EQ(unguarded.kept, 0);
  const std::vector<Eigen::VectorXd> poses = sampleMotionPoses(model.joint_names, 24, 778);
  const Error plain = errorOf(model, model, skin, poses);
  const Error g = errorOf(model, withRefit(model, guarded), skin, poses);
  const Error u = errorOf(model, withRefit(model, unguarded), skin, poses);
  EXPECT_LT(g.max, u.max) << "plain " << plain.max << " guarded " << g.max << " unguarded "
                          << u.max;
  EXPECT_LT(g.max, plain.max * 1.05);
}

TEST(CorrectiveRefit, DoesNotDependOnTheThreadCount) {
  const BodyModel& model = demoBody();
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  const SparseSkin skin = pruneWeights(model.weights, 4);
  CorrectiveRefitOptions o;
  o.threads = 1;
  const CorrectiveRefit one = refitCorrectives(model, body, skin, o);
  o.threads = 2;
  const CorrectiveRefit two = refitCorrectives(model, body, skin, o);
  EXPECT_EQ(one.block, two.block);
  EXPECT_TRUE(one.rows == two.rows);
}

TEST(CorrectiveRefit, CorrectionMatchesTheForwardPassWithRefittedPosedirs) {
  const BodyModel model = smplFixture();
  const ShapedBody body = *shapeBody(model, Eigen::VectorXd());
  const SparseSkin skin = pruneWeights(model.weights, 3);
  const CorrectiveRefit refit = refitCorrectives(model, body, skin, CorrectiveRefitOptions());
  ASSERT_FALSE(refit.empty());
  const BodyModel refitted = withRefit(model, refit);
  const Eigen::MatrixXd weights = denseWeights(skin, model.numJoints());
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), 3, 5))
    frames.push_back(rotationsFromAxisAngle(pose));
  Eigen::MatrixXd posed(3 * model.numVertices(), Eigen::Index(frames.size()));
  Eigen::MatrixXd want = posed;
  for (size_t t = 0; t < frames.size(); ++t) {
    ForwardInput in;
    in.rotations = frames[t];
    in.weights = &weights;
    const Eigen::MatrixXd a = forward(model, in)->vertices, b = forward(refitted, in)->vertices;
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      posed.block<3, 1>(3 * i, Eigen::Index(t)) = a.row(i).transpose();
      want.block<3, 1>(3 * i, Eigen::Index(t)) = b.row(i).transpose();
    }
  }
  addRefitCorrection(model, body, skin, refit, frames, &posed);
  EXPECT_LT((posed - want).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace smpl
