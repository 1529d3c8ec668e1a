// Tests for whole-file reads, atomic writes and baseName. Each test works in
// its own scratch directory so leftover temporary files can be detected.
#include "core/io/file_io.h"

#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace smpl {
namespace {

class FileIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "file_io_test_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    ::mkdir(dir_.c_str(), 0755);
  }
  void TearDown() override {
    for (const std::string& f : list()) std::remove((dir_ + "/" + f).c_str());
    ::rmdir((dir_ + "/sub").c_str());
    ::rmdir((dir_ + "/out.glb.smpl.json").c_str());
    ::rmdir(dir_.c_str());
  }
  std::vector<std::string> list() const {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir_.c_str())) {
      while (dirent* e = ::readdir(d))
        if (std::strcmp(e->d_name, ".") && std::strcmp(e->d_name, "..")) names.push_back(e->d_name);
      ::closedir(d);
    }
    return names;
  }
  std::string dir_;
};

TEST_F(FileIo, WriteThenReadRoundTripsBinaryData) {
  std::string bytes(300000, '\0');  // larger than the read chunk, with NULs
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 131) & 0xff);
  const std::string path = dir_ + "/out.glb";
  ASSERT_TRUE(writeFileAtomic(path, bytes).ok());
  Result<std::vector<uint8_t>> back = readFileBytes(path);
  ASSERT_TRUE(back.ok()) << back.message();
  EXPECT_EQ(std::string(back->begin(), back->end()), bytes);
  EXPECT_EQ(list(), std::vector<std::string>{"out.glb"});  // no temporary left behind
}

TEST_F(FileIo, OverwritesAnExistingFile) {
  const std::string path = dir_ + "/x.json";
  ASSERT_TRUE(writeFileAtomic(path, std::string("a much longer first version")).ok());
  ASSERT_TRUE(writeFileAtomic(path, std::string("v2")).ok());
  Result<std::vector<uint8_t>> back = readFileBytes(path);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(std::string(back->begin(), back->end()), "v2");
}

TEST_F(FileIo, EmptyFileReadsAsEmpty) {
  const std::string path = dir_ + "/empty";
  ASSERT_TRUE(writeFileAtomic(path, std::string()).ok());
  Result<std::vector<uint8_t>> back = readFileBytes(path);
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(back->empty());
}

TEST_F(FileIo, MissingFileReportsPathAndReason) {
  const std::string path = dir_ + "/nope.npz";
  Result<std::vector<uint8_t>> r = readFileBytes(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), path + ": cannot open: " + std::strerror(ENOENT));
}

TEST_F(FileIo, ReadingADirectoryIsAnError) {
  Result<std::vector<uint8_t>> r = readFileBytes(dir_);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), dir_ + ": not a regular file (a directory)");
}

TEST_F(FileIo, WriteIntoMissingDirectoryFailsCleanly) {
  const std::string path = dir_ + "/no/such/dir/out.glb";
  Status st = writeFileAtomic(path, std::string("x"));
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message().rfind(path + ": cannot create temporary file: ", 0), 0u) << st.message();
  EXPECT_TRUE(list().empty());
}

TEST_F(FileIo, FailedRenameRemovesTheTemporary) {
  const std::string path = dir_ + "/sub";  // a non-empty directory cannot be replaced by a file
  ASSERT_EQ(::mkdir(path.c_str(), 0755), 0);
  std::ofstream(path + "/keep") << "x";
  Status st = writeFileAtomic(path, std::string("data"));
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(path + ": cannot rename temporary file into place"),
            std::string::npos)
      << st.message();
  EXPECT_EQ(list(), std::vector<std::string>{"sub"});
  std::remove((path + "/keep").c_str());
}

std::string readText(const std::string& path) {
  Result<std::vector<uint8_t>> r = readFileBytes(path);
  return r ? std::string(r->begin(), r->end()) : "<" + r.message() + ">";
}

TEST_F(FileIo, TemporaryIsDotPrefixedAndNamedAfterTheOutput) {
  const std::string pid = std::to_string(::getpid());
  EXPECT_EQ(tempPathFor("/data/out/walk.glb"), "/data/out/.walk.glb.smpl.tmp-" + pid);
  EXPECT_EQ(tempPathFor("walk.glb"), ".walk.glb.smpl.tmp-" + pid);
}

TEST_F(FileIo, PairIsWrittenTogether) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  const std::string a = "output v1", b = "sidecar v1";
  ASSERT_TRUE(writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}}).ok());
  EXPECT_EQ(readText(out), a);
  EXPECT_EQ(readText(side), b);
  EXPECT_EQ(list().size(), 2u);  // no temporaries or backups left
}

// The sidecar cannot be renamed into place (a directory is in the way): the
// new output must be rolled back, so the old output stays, byte for byte.
TEST_F(FileIo, FailedSidecarKeepsTheOldOutput) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  ASSERT_TRUE(writeFileAtomic(out, std::string("old output")).ok());
  ASSERT_EQ(::mkdir(side.c_str(), 0755), 0);
  std::ofstream(side + "/keep") << "x";
  const std::string a = "new output", b = "new sidecar";
  Status st = writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}});
  std::remove((side + "/keep").c_str());
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find(side + ": cannot rename temporary file into place"),
            std::string::npos)
      << st.message();
  EXPECT_EQ(readText(out), "old output");
  std::vector<std::string> names = list();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"out.glb", "out.glb.smpl.json"}));  // no temporaries
}

// Same with no previous output: the new one must not stay alone.
TEST_F(FileIo, FailedSidecarLeavesNoNewOutput) {
  const std::string out = dir_ + "/out.glb", side = out + ".smpl.json";
  ASSERT_EQ(::mkdir(side.c_str(), 0755), 0);
  std::ofstream(side + "/keep") << "x";
  const std::string a = "new output", b = "new sidecar";
  Status st = writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}});
  std::remove((side + "/keep").c_str());
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(list(), std::vector<std::string>{"out.glb.smpl.json"});
}

// A failed first rename (output is a directory) leaves the old sidecar.
TEST_F(FileIo, FailedOutputKeepsTheOldSidecar) {
  const std::string out = dir_ + "/sub", side = out + ".smpl.json";
  ASSERT_TRUE(writeFileAtomic(side, std::string("old sidecar")).ok());
  ASSERT_EQ(::mkdir(out.c_str(), 0755), 0);
  std::ofstream(out + "/keep") << "x";
  const std::string a = "new output", b = "new sidecar";
  Status st = writeFilesTogether({{out, a.data(), a.size()}, {side, b.data(), b.size()}});
  std::remove((out + "/keep").c_str());
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(readText(side), "old sidecar");
  EXPECT_EQ(list().size(), 2u);
}

// Stale temporaries of our outputs (dead pid) go; a live run's, other
// outputs' and unrelated files stay.
TEST_F(FileIo, RemovesOnlyStaleTemporariesOfItsOutputs) {
  pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  int status = 0;
  ::waitpid(child, &status, 0);  // now a pid that is not alive
  pid_t sleeper = ::fork();      // another live process
  if (sleeper == 0) {
    ::pause();
    ::_exit(0);
  }
  ASSERT_GT(sleeper, 0);
  const std::string dead = std::to_string(child), live = std::to_string(sleeper);
  const std::vector<std::string> files = {".out.glb.smpl.tmp-" + dead,
                                          ".out.glb.smpl.json.smpl.tmp-" + dead,
                                          ".out.glb.smpl.tmp-" + dead + "-old",
                                          ".out.glb.smpl.tmp-" + live,
                                          ".other.glb.smpl.tmp-" + dead,
                                          "out.glb.smpl.tmp-" + dead,
                                          ".out.glb.tmp-" + dead};
  for (const std::string& f : files) std::ofstream(dir_ + "/" + f) << "x";
  std::ofstream(dir_ + "/.out.glb.smpl.json.smpl.tmp-" + std::to_string(::getpid()))
      << "x";  // this run's
  const int removed = removeStaleTemps(dir_, {"out.glb", "out.glb.smpl.json"});
  ::kill(sleeper, SIGKILL);
  ::waitpid(sleeper, &status, 0);
  EXPECT_EQ(removed, 3);
  std::vector<std::string> left = list();
  std::sort(left.begin(), left.end());
  std::vector<std::string> want = {files[3], files[4], files[5], files[6],
                                   ".out.glb.smpl.json.smpl.tmp-" + std::to_string(::getpid())};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(left, want);
}

TEST(BaseName, LastPathComponent) {
  EXPECT_EQ(baseName("/data/models/SMPLX_NEUTRAL.npz"), "SMPLX_NEUTRAL.npz");
  EXPECT_EQ(baseName("model.npz"), "model.npz");
  EXPECT_EQ(baseName("rel/dir/beta.npy"), "beta.npy");
  EXPECT_EQ(baseName("dir/"), "dir");
  EXPECT_EQ(baseName("/"), "/");
  EXPECT_EQ(baseName(""), "");
}

}  // namespace
}  // namespace smpl
