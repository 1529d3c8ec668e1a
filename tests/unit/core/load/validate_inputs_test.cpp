// Input range checks: each bound refuses what it must and keeps what it must.
#include "core/load/validate_inputs.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "core/io/npz.h"
#include "core/load/model_loader.h"

namespace smpl {
namespace {

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

Motion motionWith(const Eigen::Matrix3d& r, size_t frame = 3, size_t joint = 5) {
  Motion m;
  m.layout = ModelKind::Smpl;
  m.fps = 30;
  m.frames.assign(6, Rotations(24, Eigen::Matrix3d::Identity()));
  m.translation.assign(6, Eigen::Vector3d::Zero());
  m.frames[frame][joint] = r;
  return m;
}

TEST(ValidateInputs, CoefficientsMustBeFiniteAndBounded) {
  EXPECT_TRUE(checkCoefficients({0.5, -3, 1000, -1000}, "b.npy", "'betas'"));
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf, 1e300, 1000.5}) {
    Status st = checkCoefficients({0, bad}, "b.npy", "'betas'");
    ASSERT_FALSE(st) << bad;
    EXPECT_EQ(st.message().rfind("b.npy: 'betas'[1] is ", 0), 0u) << st.message();
  }
}

TEST(ValidateInputs, FloatRangeAndIndices) {
  Array a;
  a.data = {1, -3.4e38, 2};
  EXPECT_TRUE(checkFloatRange(a, "m.npz", "posedirs"));
  a.data[1] = 1e39;
  Status st = checkFloatRange(a, "m.npz", "posedirs");
  ASSERT_FALSE(st);
  EXPECT_EQ(
      st.message(),
      "m.npz: 'posedirs' element 1 is 1e+39, beyond the float32 range the output is written in");
  Array f;
  f.data = {0, 1, 2, 4294967295.0};
  EXPECT_FALSE(checkIndices(f, "m.npz", "f"));
  f.data = {0, 1.5, 2};
  st = checkIndices(f, "m.npz", "f");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message(), "m.npz: 'f' element 1 is 1.5; expected a non-negative integer index");
  f.data = {0, 1, 2};
  EXPECT_TRUE(checkIndices(f, "m.npz", "f"));
}

TEST(ValidateInputs, ModelWithFloatFaceIndexOrHugeValueIsRefused) {
  Result<ArrayDict> d = readNpzFile(kModels + "smpl_small.npz");
  ASSERT_TRUE(d.ok()) << d.message();
  ASSERT_TRUE(buildModel(*d, "model.npz").ok());
  ArrayDict faces = *d;
  faces["f"].data[4] += 0.5;
  Result<BodyModel> m = buildModel(faces, "model.npz");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("'f' element 4 is"), std::string::npos) << m.message();
  ArrayDict huge = *d;
  huge["shapedirs"].data[7] = 1e300;
  m = buildModel(huge, "model.npz");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("'shapedirs' element 7 is 1e+300, beyond the float32 range"),
            std::string::npos)
      << m.message();
}

TEST(ValidateInputs, FrameRates) {
  EXPECT_TRUE(checkFrameRate(120, "w.npz", "'mocap_framerate'"));
  EXPECT_TRUE(checkFrameRate(1, "w.npz", "'fps'"));
  for (double bad : {0.001, 0.0, -30.0, 10001.0, std::nan("")})
    EXPECT_FALSE(checkFrameRate(bad, "w.npz", "'fps'")) << bad;
}

TEST(ValidateInputs, ZeroScaledAndReflectedMatricesAreRefusedWithFrameAndJoint) {
  for (const Eigen::Matrix3d& bad :
       {Eigen::Matrix3d(Eigen::Matrix3d::Zero()), Eigen::Matrix3d(2 * Eigen::Matrix3d::Identity()),
        Eigen::Matrix3d(Eigen::Vector3d(1, 1, -1).asDiagonal()),
        Eigen::Matrix3d(1.01 * Eigen::Matrix3d::Identity())}) {
    Motion m = motionWith(bad);
    Status st = checkMotionValues(&m, "walk.npz");
    ASSERT_FALSE(st) << bad;
    EXPECT_EQ(st.message().rfind(
                  "walk.npz: 'poses' frame 3 joint 5 (right_knee) is not a rotation matrix", 0),
              0u)
        << st.message();
  }
}

TEST(ValidateInputs, NearRotationIsReorthonormalised) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d noisy = r;
  noisy(0, 1) += 2e-4;  // ||R^T R - I|| about 3e-4: float storage noise, within 1e-3
  Motion m = motionWith(noisy);
  ASSERT_TRUE(checkMotionValues(&m, "walk.npz"));
  const Eigen::Matrix3d fixed = m.frames[3][5];
  EXPECT_LT((fixed.transpose() * fixed - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(fixed.determinant(), 1.0, 1e-12);
  EXPECT_LT((fixed - r).norm(), 3e-4);
}

TEST(ValidateInputs, TranslationsBetasAndFpsOfAMotion) {
  Motion m = motionWith(Eigen::Matrix3d::Identity());
  ASSERT_TRUE(checkMotionValues(&m, "walk.npz"));
  m.translation[2].y() = 2e4;
  Status st = checkMotionValues(&m, "walk.npz");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message(),
            "walk.npz: 'trans' frame 2 is 20000 m; expected finite values within 10000 m");
  m = motionWith(Eigen::Matrix3d::Identity());
  m.betas = {0.1, 1e300};
  st = checkMotionValues(&m, "walk.npz");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message().rfind("walk.npz: 'betas'[1] is 1e+300", 0), 0u) << st.message();
  m = motionWith(Eigen::Matrix3d::Identity());
  m.fps = 0.001;
  EXPECT_FALSE(checkMotionValues(&m, "walk.npz"));
}

// UVs and DMPL arrays are checked where they enter, naming the input and
// key: a value beyond float32 is not left for the writer to find (exit 3,
// naming the output).
TEST(ValidateInputs, TexCoordsAndDmplArrays) {
  const double uv[4] = {0, 1, 9.5, -1000};
  EXPECT_TRUE(checkTexCoords(uv, 4, "uv.npy", "UV coordinates"));
  for (double bad : {1e39, 1000.5, std::numeric_limits<double>::quiet_NaN()}) {
    const double values[3] = {0.5, 0.5, bad};
    Status st = checkTexCoords(values, 3, "uv.npy", "UV coordinates");
    ASSERT_FALSE(st) << bad;
    EXPECT_EQ(st.message().rfind("uv.npy: UV coordinates element 2 is ", 0), 0u) << st.message();
  }
  Array eigvec;
  eigvec.shape = {2, 3, 1};
  eigvec.data = {0.01, -0.02, 0, 0, 10, -10};
  EXPECT_TRUE(checkDmplBasisValues(eigvec, "dmpl.npz"));
  eigvec.data[4] = 1e39;
  Status st = checkDmplBasisValues(eigvec, "dmpl.npz");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message(),
            "dmpl.npz: 'eigvec' element 4 is 1e+39; expected finite values within 10 m per unit "
            "coefficient");
  Eigen::MatrixXd dmpls = Eigen::MatrixXd::Constant(5, 8, 2.5);
  EXPECT_TRUE(checkDmplValues(dmpls, "walk.npz"));
  dmpls(3, 2) = -1e39;
  st = checkDmplValues(dmpls, "walk.npz");
  ASSERT_FALSE(st);
  EXPECT_EQ(st.message(),
            "walk.npz: 'dmpls' frame 3 column 2 is -1e+39; expected a finite value with magnitude "
            "at most 1000");
}

}  // namespace
}  // namespace smpl
