#include "core/motions/motion.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "core/memory_budget.h"

namespace smpl {
namespace {

const std::string kMotions = std::string(SMPL_FIXTURE_DIR) + "/motions/";

TEST(Motion, AmassSmplh) {
  Result<Motion> m = loadMotion(kMotions + "amass_smplh.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->layout, ModelKind::SmplH);
  EXPECT_EQ(m->frames.size(), 240u);
  EXPECT_EQ(m->frames[0].size(), 52u);
  EXPECT_EQ(m->fps, 120.0);
  EXPECT_EQ(m->betas.size(), 16u);
  EXPECT_EQ(m->gender, "female");
  EXPECT_EQ(m->world, MotionWorld::Z);
  EXPECT_NEAR(m->translation[100].x(), 0.2, 1e-12);
}

// After the bake (request/run_request.cpp) the per-frame arrays
// and their charge go; what names and describes the motion stays.
TEST(Motion, ReleaseFramesFreesTheFramesAndTheirCharge) {
  const uint64_t before = memoryCharged();
  Result<Motion> m = loadMotion(kMotions + "amass_smplh.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  ASSERT_GT(memoryCharged(), before);
  releaseFrames(&*m);
  EXPECT_EQ(memoryCharged(), before);
  EXPECT_TRUE(m->frames.empty() && m->frames.capacity() == 0);
  EXPECT_TRUE(m->translation.empty() && m->translation.capacity() == 0);
  EXPECT_EQ(m->dmpls.size(), 0);
  EXPECT_EQ(m->name, "amass_smplh");
  EXPECT_EQ(m->betas.size(), 16u);
  EXPECT_EQ(m->fps, 120.0);
}

TEST(Motion, AmassSmplxSplitKeys) {
  Result<Motion> m = loadMotion(kMotions + "amass_smplx.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->layout, ModelKind::SmplX);
  EXPECT_EQ(m->frames[0].size(), 55u);
  EXPECT_EQ(m->fps, 60.0);
  EXPECT_EQ(m->world, MotionWorld::Z);
}

TEST(Motion, MatricesEqualAxisAngle) {
  Result<Motion> aa = loadMotion(kMotions + "smpl_72.npz");
  Result<Motion> mats = loadMotion(kMotions + "matrices.npz");
  ASSERT_TRUE(aa.ok()) << aa.message();
  ASSERT_TRUE(mats.ok()) << mats.message();
  EXPECT_EQ(aa->world, MotionWorld::Y);
  ASSERT_EQ(aa->frames.size(), mats->frames.size());
  for (size_t f = 0; f < aa->frames.size(); f += 7)
    for (int j = 0; j < 24; ++j)
      EXPECT_LT((aa->frames[f][j] - mats->frames[f][j]).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Motion, Json) {
  Result<Motion> m = loadMotion(kMotions + "plain.json");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->frames.size(), 20u);
  EXPECT_EQ(m->fps, 25.0);
  EXPECT_EQ(m->name, "plain");
}

// Per-frame betas rows that are all the same are one row, taken as stored:
// their mean summed in double differs from them by rounding (0.1 -> 0.0999...),
// which once made the note claim "'betas' has 30 different rows".
TEST(Motion, IdenticalBetasRowsAreOneRowWithoutANote) {
  const std::string path = ::testing::TempDir() + "identical_betas_rows.json";
  std::string rows, poses, roots;
  for (int f = 0; f < 30; ++f) {
    rows += std::string(f ? "," : "") + "[0.1, 0.7, -1.3]";
    roots += std::string(f ? "," : "") + "[0, 0, 0]";
    poses += std::string(f ? "," : "") + "[" + std::string(62 * 2, ' ') + "0";
    for (int i = 1; i < 63; ++i) poses += ",0";
    poses += "]";
  }
  {
    std::ofstream out(path);
    out << R"({"global_orient": [)" << roots << R"(], "body_pose": [)" << poses
        << R"(], "betas": [)" << rows << "]}";
  }
  Result<Motion> m = loadMotion(path);
  std::remove(path.c_str());
  ASSERT_TRUE(m.ok()) << m.message();
  ASSERT_EQ(m->betas.size(), 3u);
  EXPECT_EQ(m->betas[0], 0.1);
  EXPECT_EQ(m->betas[1], 0.7);
  EXPECT_EQ(m->betas[2], -1.3);
  for (const std::string& note : m->notes)
    EXPECT_EQ(note.find("different rows"), std::string::npos) << note;
}

TEST(Motion, BadInputsNameFileAndProblem) {
  struct Bad {
    const char* file;
    const char* text;
  };
  for (const Bad& b :
       {Bad{"bad_trans.npz", "'trans' has shape (10,3); expected (60,3)"},
        Bad{"bad_nan.npz", "'poses' contains NaN"}, Bad{"bad_joints.npz", "'poses' has 21 joints"},
        Bad{"missing.npz", "missing.npz"}}) {
    Result<Motion> m = loadMotion(kMotions + b.file);
    ASSERT_FALSE(m.ok()) << b.file;
    EXPECT_NE(m.message().find(b.text), std::string::npos) << m.message();
    EXPECT_NE(m.message().find(b.file), std::string::npos) << m.message();
  }
}

}  // namespace
}  // namespace smpl
