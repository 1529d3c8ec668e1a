// Animated SMPL-X expressions (exporter/expression_targets.h): the baked
// expr_<i> weights reproduce v_shaped(betas, psi(t)) exactly where the joints
// do not matter, the fixed-joint cost bounds the error against the authors'
// math (joints regressed from the expressive template), and the notes say
// what was not baked.
#include "exporter/expression_targets.h"

#include <gtest/gtest.h>

#include <random>

#include "core/math/forward.h"
#include "core/models/model_loader.h"
#include "exporter/animation.h"
#include "exporter/export_asset.h"
#include "tests/unit/test_asset.h"

namespace smpl {
namespace {

const std::string kModel = std::string(SMPL_FIXTURE_DIR) + "/models/smplx_small.npz";

// T frames of random rotations (|angle| <= `angle`), translations and
// expression coefficients in [-2, 2] (E of them).
Motion randomMotion(const BodyModel& model, int t, int e, double angle, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Motion m;
  m.name = "talk";
  m.layout = ModelKind::SmplX;
  m.fps = 30;
  m.expression.resize(t, e);
  for (int f = 0; f < t; ++f) {
    Eigen::VectorXd aa(3 * model.numJoints());
    for (Eigen::Index i = 0; i < aa.size(); ++i) aa[i] = angle * u(rng);
    m.frames.push_back(rotationsFromAxisAngle(aa));
    m.translation.emplace_back(u(rng), u(rng), u(rng));
    for (int i = 0; i < e; ++i) m.expression(f, i) = 2 * u(rng);
  }
  return m;
}

// The authors' math at frame f: joints regressed from v_shaped(betas, psi(f)).
Eigen::MatrixXd published(const BodyModel& model, const Motion& m, int f, int used,
                          const Eigen::MatrixXd& skin) {
  ForwardInput in;
  in.expression = m.expression.row(f).head(used).transpose();
  in.rotations = m.frames[f];
  in.translation = m.translation[f];
  in.weights = &skin;
  Result<ForwardResult> r = forward(model, in);
  EXPECT_TRUE(r.ok()) << r.message();
  return r->vertices;
}

struct Baked {
  BodyModel model;
  Motion motion;
  Asset asset;
  Eigen::MatrixXd skin;  // the exported skin, dense N x K
};

Baked bake(int keys, double angle) {
  Baked b;
  Result<BodyModel> model = loadModel(kModel);
  EXPECT_TRUE(model.ok()) << model.message();
  b.model = *model;
  b.motion = randomMotion(b.model, 6, 20, angle, 5);
  ExportOptions o;
  o.expression_keys = keys;
  o.max_influences = kAllInfluences;  // the model's own skin: only the joints differ
  Result<Asset> a = exportAsset(b.model, o, {MotionInput{&b.motion, "talk.npz", {}, nullptr}});
  EXPECT_TRUE(a.ok()) << a.message();
  b.asset = *a;
  b.skin = Eigen::MatrixXd::Zero(b.model.numVertices(), b.model.numJoints());
  for (Eigen::Index i = 0; i < b.asset.mesh.joints.rows(); ++i)
    for (Eigen::Index k = 0; k < b.asset.mesh.joints.cols(); ++k)
      b.skin(i, b.asset.mesh.joints(i, k)) += b.asset.mesh.weights(i, k);
  return b;
}

TEST(ExpressionTargets, BakedWeightsReproduceTheExpressionAtRest) {
  Baked b = bake(10, 0.0);  // rest rotations: joints do not move the skin
  const AnimationClip& clip = b.asset.animations[0];
  ASSERT_EQ(b.asset.metadata.expression_targets.targets.size(), 10u);
  for (int f = 0; f < 6; ++f) {
    for (const ExpressionLayout& e : b.asset.metadata.expression_targets.targets) {
      int t = 0;
      while (b.asset.mesh.morph_targets[t].name != e.target) ++t;
      EXPECT_GE(clip.morph_weights(f, t), -1e-6f);  // importers that clamp play it exactly
      EXPECT_LE(clip.morph_weights(f, t), 1 + 1e-6f);
    }
    const double err =
        (test::enginePlayback(b.asset, clip, f) - published(b.model, b.motion, f, 10, b.skin))
            .rowwise()
            .norm()
            .maxCoeff();
    EXPECT_LT(err, 1e-5) << "frame " << f;  // float32 deltas and weights
  }
  EXPECT_LT(clip.expression_joint_error, 1e-9);
}

TEST(ExpressionTargets, FixedJointsCostBoundsTheErrorAgainstTheAuthorsMath) {
  Baked b = bake(10, 0.6);
  const AnimationClip& clip = b.asset.animations[0];
  double worst = 0;
  for (int f = 0; f < 6; ++f)
    worst = std::max(worst, (test::enginePlayback(b.asset, clip, f) -
                             published(b.model, b.motion, f, 10, b.skin))
                                .rowwise()
                                .norm()
                                .maxCoeff());
  EXPECT_GT(worst, 1e-4);                                // the joints do follow the expression
  EXPECT_LE(worst, clip.expression_joint_error + 1e-5);  // and the cost measures it
  EXPECT_GE(worst, clip.expression_joint_error - 1e-5);  // every frame is sampled here
  bool noted = false, dropped = false;
  for (const std::string& n : clip.notes) {
    noted |= n.find("the joints follow the expression, this costs up to") != std::string::npos;
    dropped |= n.find(
                   "10 of the motion's 20 expression coefficients are baked "
                   "(--expression-keys 10); the largest dropped |value| is") != std::string::npos;
  }
  EXPECT_TRUE(noted);
  EXPECT_TRUE(dropped);
}

TEST(ExpressionTargets, WithoutKeysNothingIsBakedAndANoteSaysSo) {
  Baked b = bake(0, 0.3);
  EXPECT_TRUE(b.asset.metadata.expression_targets.targets.empty());
  const AnimationClip& clip = b.asset.animations[0];
  ASSERT_FALSE(clip.notes.empty());
  EXPECT_NE(clip.notes[0].find("the motion has 20 SMPL-X expression coefficients per frame"),
            std::string::npos)
      << clip.notes[0];
  EXPECT_NE(clip.notes[0].find("add --expression-keys"), std::string::npos) << clip.notes[0];
}

TEST(ExpressionTargets, StaticExportsKeepCoefficientWeights) {
  Result<BodyModel> model = loadModel(kModel);
  ASSERT_TRUE(model.ok());
  ExportOptions o;
  o.expression_keys = 5;
  Result<Asset> a = exportAsset(*model, o, {});
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_TRUE(a->metadata.expression_targets.targets.empty());
  for (const MorphTarget& t : a->mesh.morph_targets)
    if (t.name.rfind("expr_", 0) == 0) EXPECT_EQ(t.rest_weight, 0.0f);
}

}  // namespace
}  // namespace smpl
