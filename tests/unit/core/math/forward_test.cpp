// The C++ forward pass against the independent numpy implementation in
// tests/fixtures/make_models.py, for every layout and container: 1e-9 m.
#include "core/math/forward.h"

#include <gtest/gtest.h>

#include "core/io/npz.h"
#include "core/models/model_loader.h"

namespace smpl {
namespace {

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

Eigen::MatrixXd slice(const Array& a, int64_t index, int64_t rows, int64_t cols) {
  const double* p = a.data.data() + index * rows * cols;
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      p, rows, cols);
}

struct Case {
  const char* layout;
  const char* file;
};

class ForwardReference : public ::testing::TestWithParam<Case> {};

TEST_P(ForwardReference, MatchesNumpyTo1e9) {
  const Case c = GetParam();
  Result<BodyModel> model = loadModel(kModels + c.file);
  ASSERT_TRUE(model.ok()) << model.message();
  Result<ArrayDict> ref = readNpzFile(kModels + c.layout + "_small_reference.npz");
  ASSERT_TRUE(ref.ok()) << ref.message();
  const ArrayDict& r = *ref;
  const int64_t poses = r.at("poses").shape[0], k = model->numJoints(), n = model->numVertices();
  const int64_t b = r.at("betas").shape[1], e = r.at("expression").shape[1];
  EXPECT_EQ(b, model->numBetas());
  EXPECT_EQ(e, model->numExpressions());
  for (int64_t i = 0; i < poses; ++i) {
    ForwardInput in;
    in.betas = slice(r.at("betas"), i, b, 1);
    in.expression = slice(r.at("expression"), i, e, 1);
    in.rotations = rotationsFromAxisAngle(Eigen::VectorXd(slice(r.at("poses"), i, 3 * k, 1)));
    in.translation = slice(r.at("trans"), i, 3, 1);
    Result<ForwardResult> out = forward(*model, in);
    ASSERT_TRUE(out.ok()) << out.message();
    EXPECT_LT((out->v_shaped - slice(r.at("v_shaped"), i, n, 3)).cwiseAbs().maxCoeff(), 1e-9)
        << "pose " << i;
    EXPECT_LT((out->joints - slice(r.at("joints"), i, k, 3)).cwiseAbs().maxCoeff(), 1e-9)
        << "pose " << i;
    EXPECT_LT(
        (out->pose_features - slice(r.at("features"), i, 9 * (k - 1), 1)).cwiseAbs().maxCoeff(),
        1e-9);
    EXPECT_LT((out->vertices - slice(r.at("vertices"), i, n, 3)).cwiseAbs().maxCoeff(), 1e-9)
        << "pose " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllContainers, ForwardReference,
    ::testing::Values(
        Case{"smpl", "smpl_small.npz"}, Case{"smpl", "smpl_small_compressed.npz"},
        Case{"smpl", "smpl_small_p2.pkl"}, Case{"smpl", "smpl_small_p4.pkl"},
        Case{"smplh", "smplh_small.npz"}, Case{"smplh", "smplh_small_p2.pkl"},
        Case{"smplh", "smplh_small_p4.pkl"}, Case{"smplx", "smplx_small.npz"},
        Case{"smplx", "smplx_small_p2.pkl"}, Case{"smplx", "smplx_small_p4.pkl"},
        Case{"mano", "mano_small.npz"}, Case{"mano", "mano_small_p2.pkl"},
        Case{"mano", "mano_small_p4.pkl"},
        // the SMPL-X release layout: object arrays, UVs, landmarks (same model arrays)
        Case{"smplx", "../released/smplx_release.npz"}),
    [](const ::testing::TestParamInfo<Case>& info) {
      std::string name = info.param.file;
      for (char& ch : name)
        if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(Rodrigues, ZeroAndHalfTurn) {
  EXPECT_TRUE(rodrigues(Eigen::Vector3d::Zero()).isApprox(Eigen::Matrix3d::Identity()));
  Eigen::Matrix3d half = rodrigues(Eigen::Vector3d(0, M_PI, 0));
  EXPECT_NEAR(half(0, 0), -1.0, 1e-12);
  EXPECT_NEAR(half(2, 2), -1.0, 1e-12);
  EXPECT_NEAR(half(1, 1), 1.0, 1e-12);
}

TEST(PoseFeatures, RowMajorLayout) {
  Rotations rots(3, Eigen::Matrix3d::Identity());
  rots[2](0, 1) = 5.0;  // joint 2, row 0, column 1 -> feature 9*(2-1) + 0*3 + 1
  Eigen::VectorXd f = poseFeatures(rots);
  ASSERT_EQ(f.size(), 18);
  EXPECT_EQ(f[10], 5.0);
  EXPECT_EQ(f.cwiseAbs().sum(), 5.0);
}

TEST(Forward, RejectsTooManyBetasAndWrongJointCount) {
  Result<BodyModel> model = loadModel(kModels + "smpl_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  ForwardInput in;
  in.rotations.assign(24, Eigen::Matrix3d::Identity());
  in.betas = Eigen::VectorXd::Zero(11);
  Result<ForwardResult> out = forward(*model, in);
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.message().find("betas: 11 values given; the model has 10"), std::string::npos)
      << out.message();
  in.betas.resize(0);
  in.rotations.resize(23);
  EXPECT_FALSE(forward(*model, in).ok());
}

}  // namespace
}  // namespace smpl
