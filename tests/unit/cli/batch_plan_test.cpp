// planBatch's up-to-date decision checks the outputs themselves: the sidecar
// records the size and SHA-256 of every file of the output (a .gltf's .bin
// too), and an output truncated, edited or missing its buffer is rebuilt even
// though its sidecar still matches.
#include "cli/batch_plan.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "request/run_request.h"

namespace smpl {
namespace {

namespace fs = std::filesystem;

class BatchPlanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "batch_plan_test_" + std::to_string(::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_ + "/motions");
    fs::create_directories(dir_ + "/out");
    fs::copy_file(std::string(SMPL_FIXTURE_DIR) + "/motions/smpl_72.npz",
                  dir_ + "/motions/walk.npz");
  }
  void TearDown() override { fs::remove_all(dir_); }
  Settings settings(const char* format) const {
    const std::string motions = dir_ + "/motions", out = dir_ + "/out";
    // Truncated weights, no refit: the plan is under test, not the fit (quicker).
    std::vector<const char*> argv = {
        "smpl-export",        "--model",  "builtin", "--motion-dir", motions.c_str(),  "--out-dir",
        out.c_str(),          "--format", format,    "-q",           "--skin-weights", "truncated",
        "--corrective-refit", "off"};
    Result<Settings> s = parseSettings(static_cast<int>(argv.size()), argv.data());
    EXPECT_TRUE(s.ok()) << s.message();
    return *s;
  }
  // Plans, converts what is not up to date, and returns whether the (one)
  // output was up to date.
  bool planAndConvert(const Settings& s) {
    EXPECT_TRUE(beginRun(s.request).ok());
    Result<BatchPlan> plan = planBatch(s);
    EXPECT_TRUE(plan.ok()) << plan.message();
    EXPECT_EQ(plan->outputs.size(), 1u);
    const PlannedOutput& p = plan->outputs[0];
    if (!p.up_to_date) {  // as cli/batch.cpp runs a planned output
      ModelSource models(s.request.model);
      Result<RunInputs> inputs = loadRunInputs(s.request, &models);
      EXPECT_TRUE(inputs.ok()) << inputs.message();
      ExportRequest job = s.request;
      job.out = p.out;
      job.motions = {p.motion};
      job.producer_hash = p.producer_hash;
      job.clean_temporaries = false;
      Result<ExportReport> r = runExportJob(job, *inputs, &models);
      EXPECT_TRUE(r.ok()) << r.message();
    }
    return p.up_to_date;
  }
  std::string dir_;
};

void truncateTo(const std::string& path, off_t size) {
  ASSERT_EQ(::truncate(path.c_str(), size), 0);
}

void flipLastByte(const std::string& path) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(-1, std::ios::end);
  const char c = static_cast<char>(f.get() ^ 1);
  f.seekp(-1, std::ios::end);
  f.put(c);
}

TEST_F(BatchPlanTest, TruncatedOrEditedOutputIsRebuilt) {
  const Settings s = settings("glb");
  const std::string out = dir_ + "/out/walk.glb";
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_TRUE(planAndConvert(s));  // unchanged: up to date
  const auto size = fs::file_size(out);
  truncateTo(out, 100);  // the reported case: an output cut to 100 bytes
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_EQ(fs::file_size(out), size);
  EXPECT_TRUE(planAndConvert(s));
  flipLastByte(out);  // same size, other bytes: the digest tells
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_TRUE(planAndConvert(s));
}

TEST_F(BatchPlanTest, GltfBufferIsCheckedToo) {
  const Settings s = settings("gltf");
  const std::string bin = dir_ + "/out/walk.bin";
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_TRUE(planAndConvert(s));
  truncateTo(bin, 16);
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_TRUE(planAndConvert(s));
  fs::remove(bin);
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_TRUE(fs::exists(bin));
}

// A sidecar without the record (written by an older version) is not trusted.
TEST_F(BatchPlanTest, SidecarWithoutOutputRecordIsRebuilt) {
  const Settings s = settings("glb");
  const std::string side = dir_ + "/out/walk.glb.smpl.json";
  EXPECT_FALSE(planAndConvert(s));
  std::ifstream in(side);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find(",\"outputs\":");
  ASSERT_NE(at, std::string::npos) << text;
  text = text.substr(0, at) + "}}";
  std::ofstream(side) << text;
  EXPECT_FALSE(planAndConvert(s));
  EXPECT_TRUE(planAndConvert(s));
}

}  // namespace
}  // namespace smpl
