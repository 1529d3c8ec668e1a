// Tests for whole-file reads, atomic writes and baseName. Each test works in
// its own scratch directory so leftover temporary files can be detected.
#include "core/io/file_io.h"

#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
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
