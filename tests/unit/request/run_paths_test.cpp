// The path guard (request/run_paths.h): same path, symbolic links
// either way, hard links and the sidecar are caught; distinct and
// not-yet-existing outputs pass; directories and devices are refused as
// outputs; the manifest may not be an output or sit in the motion folder;
// the input list covers a model folder's subfolders, the UV partner and the
// DMPL basis.
#include "request/run_paths.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace smpl {
namespace {

namespace fs = std::filesystem;

class RunPathsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "run_paths_" + std::to_string(::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    model_ = dir_ + "/model.npz";
    std::ofstream(model_) << "model bytes";
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The guard over `outputs` (and their sidecars) against `inputs`.
  Status guard(std::vector<std::string> outputs, std::vector<std::string> inputs) const {
    RunPaths paths;
    paths.inputs = std::move(inputs);
    for (const std::string& o : outputs) {
      paths.outputs.push_back(o);
      paths.outputs.push_back(o + ".smpl.json");
    }
    return checkRunPaths(paths);
  }
  bool contains(const std::vector<std::string>& list, const std::string& path) const {
    return std::find(list.begin(), list.end(), path) != list.end();
  }
  std::string dir_, model_;
};

TEST_F(RunPathsTest, SamePathSymlinkHardLinkAndSidecarAreRefused) {
  EXPECT_FALSE(guard({model_}, {model_}).ok());
  ASSERT_EQ(::symlink(model_.c_str(), (dir_ + "/link.glb").c_str()), 0);
  Status st = guard({dir_ + "/link.glb"}, {model_});
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "output " + dir_ + "/link.glb would overwrite the input " + model_ +
                              " (same file); choose another output path");
  EXPECT_EQ(st.kind(), ErrorKind::Usage);
  ASSERT_EQ(::link(model_.c_str(), (dir_ + "/hard.glb").c_str()), 0);
  EXPECT_FALSE(guard({dir_ + "/hard.glb"}, {model_}).ok());
  ASSERT_EQ(::symlink((dir_ + "/hard.glb").c_str(), (dir_ + "/in_link.npz").c_str()), 0);
  EXPECT_FALSE(guard({dir_ + "/hard.glb"}, {dir_ + "/in_link.npz"}).ok());
  std::ofstream(dir_ + "/model.npz.smpl.json") << "{}";
  EXPECT_FALSE(guard({model_}, {dir_ + "/model.npz.smpl.json"}).ok());
}

TEST_F(RunPathsTest, DistinctOrNewOutputsPass) {
  std::ofstream(dir_ + "/other.glb") << "model bytes";  // same bytes, another file
  EXPECT_TRUE(guard({dir_ + "/other.glb"}, {model_}).ok());
  EXPECT_TRUE(guard({dir_ + "/new.glb"}, {model_, dir_ + "/missing.npz"}).ok());
  EXPECT_TRUE(guard({dir_ + "/other.glb"}, {}).ok());
}

TEST_F(RunPathsTest, DirectoriesAndDevicesAreNotOutputs) {
  fs::create_directories(dir_ + "/folder.glb");
  Status st = guard({dir_ + "/folder.glb"}, {model_});
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "output " + dir_ +
                              "/folder.glb is a directory, not a file; choose another output path");
  fs::create_directories(dir_ + "/a.glb.smpl.json");  // the sidecar's place
  st = guard({dir_ + "/a.glb"}, {model_});
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("a.glb.smpl.json is a directory"), std::string::npos);
  for (const char* device : {"/dev/full", "/dev/null"}) {
    RunPaths paths;
    paths.outputs = {device};
    Status dev = checkRunPaths(paths);
    ASSERT_FALSE(dev.ok()) << device;
    EXPECT_EQ(dev.message(), std::string("output ") + device +
                                 " is a character device, not a file; choose another output path");
  }
}

TEST_F(RunPathsTest, ManifestIsNotAnOutputNorInTheMotionFolder) {
  ExportRequest r;
  r.model = "builtin";
  r.motion_dir = dir_ + "/motions";
  fs::create_directories(r.motion_dir);
  r.manifest = dir_ + "/out/walk.glb";  // = a planned output, which does not exist yet
  Status st = checkRunPaths(runPaths(r, {dir_ + "/out/walk.glb"}, {}));
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "outputs " + dir_ + "/out/walk.glb and " + dir_ +
                              "/out/walk.glb (--manifest) are the same file; choose another path");
  r.manifest = dir_ + "/motions/../motions/m.jsonl";  // directly in the motion folder
  st = checkRunPaths(runPaths(r, {dir_ + "/out/walk.glb"}, {}));
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "--manifest " + r.manifest + " is in the --motion-dir folder " +
                              r.motion_dir +
                              " (the next run would read it as a motion); choose another folder");
  r.manifest = dir_ + "/m.jsonl";
  EXPECT_TRUE(checkRunPaths(runPaths(r, {dir_ + "/out/walk.glb"}, {})).ok());
}

TEST_F(RunPathsTest, InputsCoverFoldersPartnersAndDmpl) {
  fs::create_directories(dir_ + "/models/smplh/male");
  std::ofstream(dir_ + "/models/smplh/male/model.npz") << "x";
  std::ofstream(dir_ + "/body_uv.npy") << "x";
  std::ofstream(dir_ + "/body_ft.npy") << "x";
  ExportRequest r;
  r.model = dir_ + "/models";
  r.asset.uv_obj = dir_ + "/body_uv.npy";
  r.dmpl = dir_ + "/dmpl.npz";
  r.betas_file = dir_ + "/b.npy";
  r.out = dir_ + "/o.gltf";
  const RunPaths paths = runPaths(r, {r.out}, {dir_ + "/walk.npz"});
  for (const std::string& in :
       {dir_ + "/models/smplh/male/model.npz", dir_ + "/body_uv.npy", dir_ + "/body_ft.npy",
        dir_ + "/dmpl.npz", dir_ + "/b.npy", dir_ + "/walk.npz"})
    EXPECT_TRUE(contains(paths.inputs, in)) << in;
  for (const std::string& out : {dir_ + "/o.gltf", dir_ + "/o.gltf.smpl.json", dir_ + "/o.bin"})
    EXPECT_TRUE(contains(paths.outputs, out)) << out;
  r.dmpl = dir_ + "/models";  // a folder: each basis it may pick
  EXPECT_TRUE(contains(runPaths(r, {r.out}, {}).inputs, dir_ + "/models/dmpls/female/model.npz"));
  r.gltf_embed = true;
  EXPECT_FALSE(contains(runPaths(r, {r.out}, {}).outputs, dir_ + "/o.bin"));
}

}  // namespace
}  // namespace smpl
