// The ecosystem's motion layouts (core/motions/motion_smplcodec, motion_fit,
// motion_aist; fixtures from tests/fixtures/make_motion_formats.py), the
// frame-rate rule and the no-pose-data rule of core/motions/motion.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/io/npz.h"
#include "core/io/pickle/pickle.h"
#include "core/models/model_loader.h"
#include "core/motions/motion.h"
#include "core/motions/motion_fit.h"

namespace smpl {
namespace {

const std::string kFormats = std::string(SMPL_FIXTURE_DIR) + "/formats/";
const std::string kMotions = std::string(SMPL_FIXTURE_DIR) + "/motions/";
const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

bool hasNote(const Motion& m, const std::string& text) {
  for (const std::string& n : m.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

double rotationError(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// Axis-angle triple j of frame f of a (T,J,3) array.
Eigen::Matrix3d stored(const Array& a, int64_t f, int64_t j) {
  const double* p = a.data.data() + (f * a.shape[1] + j) * 3;
  return rodrigues(Eigen::Vector3d(p[0], p[1], p[2]));
}

TEST(MotionFormats, SmplCodecWithRoot) {
  Result<Motion> m = loadMotion(kFormats + "codec_root.smpl");
  ASSERT_TRUE(m.ok()) << m.message();
  Result<ArrayDict> raw = readNpzFile(kFormats + "codec_root.smpl");
  ASSERT_TRUE(raw.ok()) << raw.message();
  const Array& body = raw->at("bodyPose");
  EXPECT_EQ(m->layout, ModelKind::SmplX);
  ASSERT_EQ(m->frames.size(), 40u);
  EXPECT_EQ(m->fps, 30.0);
  EXPECT_FALSE(m->fps_assumed);
  EXPECT_EQ(m->gender, "male");
  EXPECT_EQ(m->betas.size(), 10u);
  EXPECT_NEAR(m->translation[10].x(), 0.1, 1e-6);
  for (int64_t f : {0, 17, 39}) {
    for (int64_t j : {0, 5, 21})
      EXPECT_LT(rotationError(m->frames[f][j], stored(body, f, j)), 1e-12) << f << " " << j;
    for (int64_t j = 0; j < 3; ++j)  // headPose: jaw, left eye, right eye
      EXPECT_LT(rotationError(m->frames[f][22 + j], stored(raw->at("headPose"), f, j)), 1e-12);
    EXPECT_LT(rotationError(m->frames[f][25 + 4], stored(raw->at("leftHandPose"), f, 4)), 1e-12);
    EXPECT_LT(rotationError(m->frames[f][40 + 14], stored(raw->at("rightHandPose"), f, 14)), 1e-12);
  }
  // expressionParameters (T,E): per-frame coefficients, baked with --expression-keys
  const Array& expression = raw->at("expressionParameters");
  ASSERT_EQ(m->expression.rows(), 40);
  ASSERT_EQ(m->expression.cols(), expression.shape[1]);
  EXPECT_EQ(m->expression(17, 3), expression.data[17 * expression.shape[1] + 3]);
}

TEST(MotionFormats, SmplCodecWithoutRoot) {
  Result<Motion> with = loadMotion(kFormats + "codec_root.smpl");
  Result<Motion> m = loadMotion(kFormats + "codec_noroot.smpl");
  ASSERT_TRUE(m.ok()) << m.message();
  ASSERT_TRUE(with.ok());
  ASSERT_EQ(m->frames.size(), 40u);
  for (int64_t f : {0, 20, 39}) {
    EXPECT_LT(rotationError(m->frames[f][0], Eigen::Matrix3d::Identity()), 1e-15);
    EXPECT_GT(rotationError(with->frames[f][0], Eigen::Matrix3d::Identity()),
              1e-3);  // the fixture's root is posed
    for (int j = 1; j < 55; ++j)
      EXPECT_LT(rotationError(m->frames[f][j], with->frames[f][j]), 1e-15) << j;
  }
  EXPECT_TRUE(hasNote(*m, "root stays at rest"));
  EXPECT_TRUE(m->fps_assumed);  // no frameRate in this file
  EXPECT_EQ(m->fps, 30.0);
}

TEST(MotionFormats, ShapeOnlyFilesHaveNoPoseData) {
  for (const std::string& path : {kFormats + "codec_shape.smpl", kFormats + "subject/shape.npz",
                                  kFormats + "subject/S1_stagei.npz"}) {
    Result<bool> poses = hasPoseData(path);
    ASSERT_TRUE(poses.ok()) << poses.message();
    EXPECT_FALSE(*poses) << path;
    Result<Motion> m = loadMotion(path);
    ASSERT_FALSE(m.ok());
    EXPECT_NE(m.message().find("no pose data"), std::string::npos) << m.message();
  }
  for (const std::string& path :
       {kFormats + "subject/walk_poses.npz", kFormats + "subject/run_stageii.npz",
        kFormats + "broken_poses.npz", kFormats + "fit_pca.pkl", kFormats + "aist.pkl"}) {
    Result<bool> poses = hasPoseData(path);
    ASSERT_TRUE(poses.ok()) << poses.message();
    EXPECT_TRUE(*poses) << path;
  }
  Result<Motion> broken = loadMotion(kFormats + "broken_poses.npz");
  ASSERT_FALSE(broken.ok());
  EXPECT_NE(broken.message().find("NaN"), std::string::npos) << broken.message();
}

// Vertices of frame f of a fit through the C++ reference forward pass.
Eigen::MatrixXd fitVertices(const BodyModel& model, const Motion& m, size_t f) {
  ForwardInput in;
  in.betas =
      Eigen::Map<const Eigen::VectorXd>(m.betas.data(), static_cast<Eigen::Index>(m.betas.size()));
  in.rotations = m.frames[f];
  in.translation = m.translation[f];
  Result<ForwardResult> r = forward(model, in);
  EXPECT_TRUE(r.ok()) << r.message();
  return r ? r->vertices : Eigen::MatrixXd();
}

double maxDifference(const Eigen::MatrixXd& v, const Array& reference, int64_t offset) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(v(i, c) - reference.data[offset + 3 * i + c]));
  return worst;
}

TEST(MotionFormats, PcaHandFitMatchesNumpyAuthorsMath) {
  Result<BodyModel> model = loadModel(kModels + "smplx_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  for (bool flat : {false, true}) {
    Result<Motion> m = loadMotion(kFormats + "fit_pca.pkl");
    ASSERT_TRUE(m.ok()) << m.message();
    EXPECT_EQ(m->layout, ModelKind::SmplX);
    ASSERT_EQ(m->frames.size(), 1u);
    EXPECT_TRUE(m->hands.active());
    ASSERT_TRUE(resolveFitHands(*model, flat, "fit_pca.pkl", &*m).ok());
    EXPECT_FALSE(m->hands.active());
    Result<ArrayDict> ref =
        readNpzFile(kFormats + (flat ? "fit_pca_flat_reference.npz" : "fit_pca_reference.npz"));
    ASSERT_TRUE(ref.ok()) << ref.message();
    const double err = maxDifference(fitVertices(*model, *m, 0), ref->at("vertices"), 0);
    EXPECT_LT(err, 1e-9) << "flat_hand_mean " << flat;
    std::printf("PCA-hand fit vs numpy (flat_hand_mean=%d): max vertex error %.3g m\n", flat, err);
  }
}

TEST(MotionFormats, FullPoseFitWithMatricesMatchesNumpy) {
  Result<BodyModel> model = loadModel(kModels + "smplx_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  Result<Motion> m = loadMotion(kFormats + "fit_full.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  ASSERT_EQ(m->frames.size(), 3u);
  ASSERT_TRUE(resolveFitHands(*model, false, "fit_full.npz", &*m).ok());
  Result<ArrayDict> ref = readNpzFile(kFormats + "fit_full_reference.npz");
  ASSERT_TRUE(ref.ok()) << ref.message();
  const int64_t n = model->numVertices();
  for (size_t f = 0; f < 3; ++f)
    EXPECT_LT(maxDifference(fitVertices(*model, *m, f), ref->at("vertices"),
                            static_cast<int64_t>(f) * n * 3),
              1e-9)
        << f;
}

TEST(MotionFormats, FitHandsNeedTheModelsPcaAndMean) {
  Result<BodyModel> model = loadModel(kModels + "smplx_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  BodyModel no_components = *model, no_mean = *model;
  no_components.hands_components_l.resize(0, 45);
  no_mean.hands_mean_r.resize(0);
  Result<Motion> m = loadMotion(kFormats + "fit_pca.pkl");
  ASSERT_TRUE(m.ok()) << m.message();
  Motion a = *m, b = *m, c = *m;
  Status s = resolveFitHands(no_components, false, "fit_pca.pkl", &a);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("'hands_componentsl'"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("fit_pca.pkl"), std::string::npos) << s.message();
  s = resolveFitHands(no_mean, false, "fit_pca.pkl", &b);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("'hands_meanr'"), std::string::npos) << s.message();
  EXPECT_TRUE(resolveFitHands(no_mean, true, "fit_pca.pkl", &c)
                  .ok());  // flat-hand relative: no mean needed
}

TEST(MotionFormats, AistTranslationIsDividedByTheScaling) {
  Result<Motion> m = loadMotion(kFormats + "aist.pkl");
  ASSERT_TRUE(m.ok()) << m.message();
  Result<ArrayDict> raw = readPickleFile(kFormats + "aist.pkl");
  ASSERT_TRUE(raw.ok()) << raw.message();
  const Array& trans = raw->at("smpl_trans");
  EXPECT_EQ(m->layout, ModelKind::Smpl);
  ASSERT_EQ(m->frames.size(), 50u);
  for (int f : {0, 25, 49})
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(m->translation[f][c], trans.data[3 * f + c] / 2.5, 1e-12);
  EXPECT_EQ(m->fps, 60.0);
  EXPECT_TRUE(m->fps_assumed);
  EXPECT_TRUE(hasNote(*m, "AIST++"));
  EXPECT_EQ(m->world, MotionWorld::Y);  // Y-up world
}

TEST(MotionFormats, FrameRateAssumedOrStated) {
  Result<Motion> assumed = loadMotion(kFormats + "no_fps.npz");
  ASSERT_TRUE(assumed.ok()) << assumed.message();
  EXPECT_EQ(assumed->fps, 30.0);
  EXPECT_TRUE(assumed->fps_assumed);
  EXPECT_TRUE(hasNote(*assumed, "assumed 30 fps"));
  MotionOptions stated;
  stated.source_fps = 24.0;
  Result<Motion> given = loadMotion(kFormats + "no_fps.npz", stated);
  ASSERT_TRUE(given.ok()) << given.message();
  EXPECT_EQ(given->fps, 24.0);
  EXPECT_FALSE(given->fps_assumed);
  EXPECT_TRUE(given->notes.empty());
  Result<Motion> stored = loadMotion(kMotions + "amass_smplh.npz", stated);  // stores 120
  ASSERT_TRUE(stored.ok()) << stored.message();
  EXPECT_EQ(stored->fps, 24.0);
  EXPECT_TRUE(hasNote(*stored, "stored rate 120 fps is overridden by --source-fps 24"));
  Result<Motion> kept = loadMotion(kMotions + "amass_smplh.npz");
  ASSERT_TRUE(kept.ok());
  EXPECT_EQ(kept->fps, 120.0);
  EXPECT_FALSE(kept->fps_assumed);
  EXPECT_TRUE(kept->notes.empty());
}

}  // namespace
}  // namespace smpl
