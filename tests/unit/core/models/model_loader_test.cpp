// Model validation: every bad array gives one line naming the file and the problem.
#include "core/models/model_loader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/io/npz.h"
#include "core/joint_names.h"
#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::numbers;

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

ArrayDict loadArrays(const std::string& file) {
  Result<ArrayDict> d = readNpzFile(kModels + file);
  EXPECT_TRUE(d.ok()) << d.message();
  return d.ok() ? *d : ArrayDict();
}

std::string errorOf(const ArrayDict& arrays) {
  Result<BodyModel> m = buildModel(arrays, "model.npz");
  return m.ok() ? std::string("(loaded)") : m.message();
}

TEST(ModelLoader, DetectsFamiliesAndSplitsSmplxShapedirs) {
  struct Expect {
    const char* file;
    ModelKind kind;
    int joints, betas, expr;
  };
  for (const Expect& e : {Expect{"smpl_small.npz", ModelKind::Smpl, 24, 10, 0},
                          Expect{"smplh_small.npz", ModelKind::SmplH, 52, 16, 0},
                          Expect{"smplx_small.npz", ModelKind::SmplX, 55, 300, 100},
                          Expect{"mano_small.npz", ModelKind::Mano, 16, 10, 0}}) {
    Result<BodyModel> m = loadModel(kModels + e.file);
    ASSERT_TRUE(m.ok()) << m.message();
    EXPECT_EQ(m->kind, e.kind) << e.file;
    EXPECT_EQ(m->numJoints(), e.joints);
    EXPECT_EQ(m->numBetas(), e.betas);
    EXPECT_EQ(m->numExpressions(), e.expr);
    EXPECT_EQ(m->numPoseFeatures(), 9 * (e.joints - 1));
    EXPECT_EQ(m->joint_names.size(), static_cast<size_t>(e.joints));
  }
}

TEST(ModelLoader, SmplJointNamesAndParents) {
  Result<BodyModel> m = loadModel(kModels + "smpl_small.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->joint_names[0], "pelvis");
  EXPECT_EQ(m->joint_names[4], "left_knee");
  EXPECT_EQ(m->joint_names[23], "right_hand");
  EXPECT_EQ(m->parents[0], -1);
  EXPECT_EQ(m->parents[15], 12);  // head under neck
  EXPECT_EQ(m->parents[23], 21);
}

TEST(ModelLoader, HandPcaLoadedForSmplh) {
  Result<BodyModel> m = loadModel(kModels + "smplh_small.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->hands_components_l.rows(), 45);
  EXPECT_EQ(m->hands_mean_r.size(), 45);
}

TEST(ModelLoader, PosedirsShapeMismatchNamesFileKeyAndShapes) {
  ArrayDict a = loadArrays("smpl_small.npz");
  const int64_t n = a["v_template"].shape[0];
  a["posedirs"].shape = {n, 3, 200};
  a["posedirs"].data.resize(n * 3 * 200);
  EXPECT_EQ(errorOf(a), "model.npz: 'posedirs' has shape (" + std::to_string(n) +
                            ",3,200); expected (" + std::to_string(n) + ",3,207)");
}

TEST(ModelLoader, MissingKey) {
  ArrayDict a = loadArrays("smpl_small.npz");
  a.erase("J_regressor");
  EXPECT_EQ(errorOf(a), "model.npz: missing key 'J_regressor'");
}

TEST(ModelLoader, NaNIsRejected) {
  ArrayDict a = loadArrays("smpl_small.npz");
  a["shapedirs"].data[7] = std::nan("");
  EXPECT_EQ(errorOf(a), "model.npz: 'shapedirs' contains NaN or infinite values");
}

TEST(ModelLoader, UnsupportedJointCount) {
  ArrayDict a = loadArrays("smpl_small.npz");
  a["weights"].shape[1] = 12;
  EXPECT_NE(errorOf(a).find("'weights' has 12 joints"), std::string::npos) << errorOf(a);
}

TEST(ModelLoader, ParentAfterChildIsRejected) {
  ArrayDict a = loadArrays("smpl_small.npz");
  a["kintree_table"].data[5] = 9;  // joint 5's parent set to a later joint
  EXPECT_NE(errorOf(a).find("'kintree_table' gives joint 5 the parent 9"), std::string::npos)
      << errorOf(a);
}

TEST(ModelLoader, FaceIndexOutOfRange) {
  ArrayDict a = loadArrays("smpl_small.npz");
  a["f"].data[0] = 1e6;
  EXPECT_NE(errorOf(a).find("'f' indexes vertex"), std::string::npos) << errorOf(a);
}

TEST(ModelLoader, WeightsMustSumToOne) {
  ArrayDict a = loadArrays("smpl_small.npz");
  a["weights"].data[0] += 0.5;
  EXPECT_NE(errorOf(a).find("'weights' row 0 sums to"), std::string::npos) << errorOf(a);
}

TEST(ModelLoader, TextWhereNumbersExpected) {
  ArrayDict a = loadArrays("smpl_small.npz");
  Array text;
  text.dtype = "<U3";
  text.strings = {"abc"};
  a["v_template"] = text;
  EXPECT_EQ(errorOf(a), "model.npz: 'v_template' holds text, expected numbers");
}

TEST(ModelLoader, ObjectArrayWhereNumbersExpected) {
  ArrayDict a = loadArrays("smpl_small.npz");
  Array dict;
  dict.dtype = "|O";
  dict.keys = {"pelvis"};
  dict.data = {0};
  dict.shape = {1};
  a["f"] = dict;
  EXPECT_EQ(errorOf(a), "model.npz: 'f' is an object array ('|O'); expected numbers");
}

// The SMPL-X release layout: extra keys (object arrays, landmarks, a complex
// member) are never decoded; vt/ft become the model's UVs.
TEST(ModelLoader, SmplxReleaseLayoutLoadsWithItsUvs) {
  const std::string released = std::string(SMPL_FIXTURE_DIR) + "/released/";
  Result<BodyModel> m = loadModel(released + "smplx_release.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->kind, ModelKind::SmplX);
  Result<ArrayDict> uv = readNpzFile(released + "smplx_release.npz", {"vt", "ft"});
  ASSERT_TRUE(uv.ok()) << uv.message();
  ASSERT_EQ(m->texcoords.rows(), uv->at("vt").shape[0]);
  ASSERT_EQ(m->texcoord_faces.rows(), m->faces.rows());
  for (Eigen::Index i = 0; i < m->texcoord_faces.size(); ++i)
    ASSERT_EQ(m->texcoord_faces(i / 3, i % 3), uv->at("ft").data[i]);
  EXPECT_EQ(m->texcoords(5, 1), uv->at("vt").data[11]);
  Result<BodyModel> plain = loadModel(kModels + "smplx_small.npz");
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain->texcoords.rows(), 0);
  EXPECT_TRUE(m->v_template == plain->v_template && m->posedirs == plain->posedirs);
}

TEST(ModelLoader, UvIndexOutOfRangeIsOneLine) {
  Result<BodyModel> m = loadModel(std::string(SMPL_FIXTURE_DIR) + "/released/smpl_bad_ft.npz");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("smpl_bad_ft.npz: 'ft' has index "), std::string::npos) << m.message();
  EXPECT_NE(m.message().find("('vt' has "), std::string::npos) << m.message();
  ArrayDict a = loadArrays("smpl_small.npz");
  a["vt"] = numbers({4, 2}, std::vector<double>(8, 0.5));
  EXPECT_EQ(errorOf(a), "model.npz: has 'vt' but not 'ft'; UVs need both");
}

TEST(ModelLoader, NotAModelFile) {
  Result<BodyModel> m = loadModel(std::string(SMPL_SOURCE_DIR) + "/CMakeLists.txt");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("CMakeLists.txt: not a model file"), std::string::npos) << m.message();
  Result<BodyModel> missing = loadModel("/nonexistent/model.pkl");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("/nonexistent/model.pkl"), std::string::npos);
}

TEST(JointNames, SmplxEyesUseTheAuthorsNames) {
  const std::vector<std::string>& names = canonicalJointNames(ModelKind::SmplX);
  EXPECT_EQ(names[23], "left_eye_smplhf");
  EXPECT_EQ(names[24], "right_eye_smplhf");
  EXPECT_EQ(canonicalJointName("left_eye"), "left_eye_smplhf");
  EXPECT_EQ(canonicalJointName("right_eye"), "right_eye_smplhf");
  EXPECT_EQ(canonicalJointName("right_eye_smplhf"), "right_eye_smplhf");
  EXPECT_EQ(canonicalJointName("jaw"), "jaw");
}

}  // namespace
}  // namespace smpl
