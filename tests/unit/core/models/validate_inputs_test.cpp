// Input range checks: each bound refuses what it must and keeps what it must.
#include "core/models/validate_inputs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/io/npz.h"
#include "core/models/model_loader.h"

namespace smpl {
namespace {

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

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
