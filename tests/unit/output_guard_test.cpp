// checkOutputsAreNotInputs: same path, symbolic links either way, hard links
// and the sidecar are caught; distinct and not-yet-existing outputs pass.
#include "cli/output_guard.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace smpl {
namespace {

class OutputGuard : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "output_guard_" + std::to_string(::getpid());
    ::mkdir(dir_.c_str(), 0755);
    model_ = dir_ + "/model.npz";
    std::ofstream(model_) << "model bytes";
  }
  void TearDown() override {
    for (const char* f :
         {"model.npz", "link.glb", "hard.glb", "other.glb", "in_link.npz", "model.npz.smpl.json"})
      std::remove((dir_ + "/" + f).c_str());
    ::rmdir(dir_.c_str());
  }
  std::string dir_, model_;
};

TEST_F(OutputGuard, SamePathSymlinkHardLinkAndSidecarAreRefused) {
  EXPECT_FALSE(checkOutputsAreNotInputs({model_}, {model_}).ok());
  ASSERT_EQ(::symlink(model_.c_str(), (dir_ + "/link.glb").c_str()), 0);
  Status st = checkOutputsAreNotInputs({dir_ + "/link.glb"}, {model_});
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "output " + dir_ + "/link.glb would overwrite the input " + model_ +
                              " (same file); choose another output path");
  ASSERT_EQ(::link(model_.c_str(), (dir_ + "/hard.glb").c_str()), 0);
  EXPECT_FALSE(checkOutputsAreNotInputs({dir_ + "/hard.glb"}, {model_}).ok());
  ASSERT_EQ(::symlink((dir_ + "/hard.glb").c_str(), (dir_ + "/in_link.npz").c_str()), 0);
  EXPECT_FALSE(checkOutputsAreNotInputs({dir_ + "/hard.glb"}, {dir_ + "/in_link.npz"}).ok());
  std::ofstream(dir_ + "/model.npz.smpl.json") << "{}";
  EXPECT_FALSE(checkOutputsAreNotInputs({model_}, {dir_ + "/model.npz.smpl.json"}).ok());
}

TEST_F(OutputGuard, DistinctOrNewOutputsPass) {
  std::ofstream(dir_ + "/other.glb") << "model bytes";  // same bytes, another file
  EXPECT_TRUE(checkOutputsAreNotInputs({dir_ + "/other.glb"}, {model_}).ok());
  EXPECT_TRUE(checkOutputsAreNotInputs({dir_ + "/new.glb"}, {model_, dir_ + "/missing.npz"}).ok());
  EXPECT_TRUE(checkOutputsAreNotInputs({dir_ + "/other.glb"}, {}).ok());
}

}  // namespace
}  // namespace smpl
