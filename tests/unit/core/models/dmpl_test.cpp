// DMPL soft tissue (core/models/dmpl.h, exporter/dmpl_targets.h): basis and
// coefficient loading with their errors, the [0, 1] weight encoding, and the
// baked result against the published math (AMASS BodyModel: displacement added
// to the template, joints regressed from it), computed with the C++ reference
// forward pass on a model whose template is displaced, and the engine's LBS
// from the asset (base mesh + weighted morph targets, animated node transforms,
// inverse bind matrices translation(-J_k)).
#include "core/models/dmpl.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>

#include "core/math/forward.h"
#include "core/models/model_loader.h"
#include "exporter/animation.h"
#include "exporter/dmpl_targets.h"
#include "exporter/pipeline.h"
#include "tests/unit/test_asset.h"
#include "writers/writer.h"

namespace smpl {
namespace {

const std::string kDmpl = std::string(SMPL_FIXTURE_DIR) + "/dmpl";
const std::string kModel = std::string(SMPL_FIXTURE_DIR) + "/models/smplh_small.npz";

TEST(DmplBasis, LoadsEigvecAndKeepsCount) {
  Result<DmplBasis> b = loadDmplBasis(kDmpl + "/dmpl_smplh_small.npz", 624);
  ASSERT_TRUE(b.ok()) << b.message();
  EXPECT_EQ(b->directions.rows(), 3 * 624);
  EXPECT_EQ(b->directions.cols(), 8);
  EXPECT_GT(b->directions.cwiseAbs().maxCoeff(), 1e-3);
  Result<DmplBasis> three = loadDmplBasis(kDmpl + "/dmpl_smplh_small.npz", 624, 3);
  ASSERT_TRUE(three.ok()) << three.message();
  EXPECT_EQ(three->directions, b->directions.leftCols(3));
  EXPECT_FALSE(loadDmplBasis(kDmpl + "/dmpl_smplh_small.npz", 624, 9).ok());
}

TEST(DmplBasis, WrongVertexCountNamesFileAndShape) {
  Result<DmplBasis> b = loadDmplBasis(kDmpl + "/bad_vertices.npz", 624);
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.message().find(
                "bad_vertices.npz: 'eigvec' has shape (618,3,8); expected (N,3,D) with N=624"),
            std::string::npos)
      << b.message();
}

TEST(DmplBasis, FindsAmassLayoutByGender) {
  std::string note;
  Result<std::string> p = findDmplBasis(kDmpl + "/amass", "female", &note);
  ASSERT_TRUE(p.ok()) << p.message();
  EXPECT_EQ(*p, kDmpl + "/amass/dmpls/female/model.npz");
  EXPECT_TRUE(note.empty());
  Result<std::string> male = findDmplBasis(kDmpl + "/amass", "m", &note);  // no male, no neutral
  ASSERT_FALSE(male.ok());
  EXPECT_NE(male.message().find("no DMPL basis for gender 'male'"), std::string::npos)
      << male.message();
}

TEST(DmplCoefficients, ReadFromMotionAndCheckedOnlyWhenUsed) {
  Result<Motion> m = loadMotion(kDmpl + "/amass_smplh_dmpl.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->dmpls.rows(), 90);
  EXPECT_EQ(m->dmpls.cols(), 8);
  EXPECT_TRUE(checkDmplCoefficients(*m, "a.npz", 8, "basis.npz").ok());
  Result<Motion> nan = loadMotion(kDmpl + "/bad_nan.npz");  // an unneeded key never fails the load
  ASSERT_TRUE(nan.ok()) << nan.message();
  Status st = checkDmplCoefficients(*nan, kDmpl + "/bad_nan.npz", 8, "basis.npz");
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("bad_nan.npz: 'dmpls' contains NaN"), std::string::npos)
      << st.message();
  Result<Motion> width = loadMotion(kDmpl + "/bad_width.npz");
  ASSERT_TRUE(width.ok()) << width.message();
  st = checkDmplCoefficients(*width, "w.npz", 8, "basis.npz");
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(),
            "w.npz: 'dmpls' has 6 columns; the DMPL basis basis.npz has 8 directions");
  Motion huge = *m;  // finite as doubles, beyond float32: refused where it enters
  huge.dmpls(7, 1) = 1e39;
  st = checkDmplCoefficients(huge, "huge.npz", 8, "basis.npz");
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message().rfind("huge.npz: 'dmpls' frame 7 column 1 is 1e+39", 0), 0u)
      << st.message();
}

TEST(DmplLayout, WeightsSpanZeroToOneAndStaticIsRest) {
  Eigen::MatrixXd c(3, 2);
  c << -2, 0.5, 1, 0.25, 3, 1.0;
  const std::vector<DmplLayout> l = dmplLayout(2, {&c});
  // Range [min(0, min c), max(0, max c)] -> [0, 1].
  EXPECT_DOUBLE_EQ(l[0].scale * -2 + l[0].offset, 0.0);
  EXPECT_DOUBLE_EQ(l[0].scale * 3 + l[0].offset, 1.0);
  EXPECT_DOUBLE_EQ(l[1].scale * 0 + l[1].offset, 0.0);
  EXPECT_DOUBLE_EQ(l[1].scale * 1 + l[1].offset, 1.0);
  EXPECT_EQ(l[1].target, "dmpl_1");
  const std::vector<DmplLayout> rest = dmplLayout(2, {});
  EXPECT_EQ(rest[0].scale, 1.0);
  EXPECT_EQ(rest[0].offset, 0.0);
}

// The published math at source frame f (no resampling: same rate), Y-up.
Eigen::MatrixXd published(const BodyModel& model, const Asset& a, const Motion& m,
                          const DmplBasis& b, int f, const Eigen::MatrixXd& pruned) {
  BodyModel displaced = model;
  if (!a.corrective_refit->empty())
    displaced.posedirs = a.corrective_refit->posedirs(model);  // as written
  const Eigen::VectorXd d = b.directions * m.dmpls.row(f).transpose();
  for (int i = 0; i < model.numVertices(); ++i)
    for (int c = 0; c < 3; ++c) displaced.v_template(i, c) += d(3 * i + c);
  ForwardInput in;
  in.betas = Eigen::Map<const Eigen::VectorXd>(a.metadata.betas.data(), a.metadata.betas.size());
  in.rotations = m.frames[f];
  in.translation = m.translation[f];
  in.weights = &pruned;
  Result<ForwardResult> r = forward(displaced, in);
  EXPECT_TRUE(r.ok()) << r.message();
  const Eigen::Matrix3d up =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return r->vertices * up.transpose();
}

double bakeAndCompare(bool regressed, double* joint_error, Asset* baked = nullptr) {
  Result<BodyModel> model = loadModel(kModel);
  EXPECT_TRUE(model.ok()) << model.message();
  Result<Motion> m = loadMotion(kDmpl + "/amass_smplh_dmpl.npz");
  EXPECT_TRUE(m.ok()) << m.message();
  ExportOptions o;
  o.betas = m->betas;
  Result<Asset> a = buildAsset(*model, o);
  EXPECT_TRUE(a.ok()) << a.message();
  Result<DmplBasis> b = loadDmplBasis(kDmpl + "/dmpl_smplh_small.npz", model->numVertices());
  EXPECT_TRUE(b.ok()) << b.message();
  addDmplTargets(*model, *b, dmplLayout(8, {&m->dmpls}), regressed, &*a);
  Result<AnimationClip> clip = bakeAnimation(*model, *a, *m, AnimationOptions(), "m.npz");
  EXPECT_TRUE(clip.ok()) << clip.message();
  EXPECT_EQ(clip->joint_translations.empty(), !regressed);
  Eigen::MatrixXd pruned = Eigen::MatrixXd::Zero(model->numVertices(), model->numJoints());
  for (Eigen::Index i = 0; i < a->mesh.joints.rows(); ++i)
    for (Eigen::Index k = 0; k < a->mesh.joints.cols(); ++k)
      pruned(i, a->mesh.joints(i, k)) += a->mesh.weights(i, k);
  double worst = 0;
  for (int f = 0; f < 90; f += 7) {
    const Eigen::MatrixXd e =
        test::enginePlayback(*a, *clip, f) - published(*model, *a, *m, *b, f, pruned);
    worst = std::max(worst, e.rowwise().norm().maxCoeff());
  }
  *joint_error = clip->dmpl_joint_error;
  if (baked) {
    a->animations.push_back(*clip);
    *baked = *a;
  }
  return worst;
}

TEST(DmplBake, RegressedJointsMatchPublishedMath) {
  double joint_error = 0;
  EXPECT_LT(bakeAndCompare(true, &joint_error), 2e-5);  // float32 deltas and weights
  EXPECT_GT(joint_error, 1e-3);                         // what fixed joints would cost
}

TEST(DmplBake, FixedJointsCostIsMeasured) {
  double joint_error = 0;
  const double err = bakeAndCompare(false, &joint_error);
  EXPECT_GT(err, 1e-3);
  EXPECT_LE(err, joint_error + 2e-5);  // the measured cost bounds the error at the sampled frames
}

// Both writers serialise the per-joint translation tracks and refuse a track
// of the wrong length.
TEST(DmplBake, WritersTakeJointTranslations) {
  double joint_error = 0;
  Asset a;
  bakeAndCompare(true, &joint_error, &a);
  for (const char* out : {"x.glb", "x.fbx"}) {
    const Writer* w = writerForPath(out);
    ASSERT_NE(w, nullptr);
    Result<std::string> bytes = w->serialize(a, WriterOptions());
    ASSERT_TRUE(bytes.ok()) << out << ": " << bytes.message();
  }
  a.animations[0].joint_translations[5].pop_back();
  for (const char* out : {"x.glb", "x.fbx"}) {
    Result<std::string> bad = writerForPath(out)->serialize(a, WriterOptions());
    ASSERT_FALSE(bad.ok()) << out;
    EXPECT_NE(bad.message().find("translation track"), std::string::npos) << bad.message();
  }
}

}  // namespace
}  // namespace smpl
