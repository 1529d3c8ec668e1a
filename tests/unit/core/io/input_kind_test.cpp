// Inputs that are not what they claim are refused from their first bytes and
// their size, before they are read whole (core/io/input_kind.h, file_io.h):
// a 3 GB sparse file costs one 4 KiB read.
#include "core/io/input_kind.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/memory_budget.h"

namespace smpl {
namespace {

namespace fs = std::filesystem;

FileFormat sniff(const std::string& head) {
  return sniffFormat(reinterpret_cast<const uint8_t*>(head.data()), head.size());
}

TEST(InputKind, SniffsByTheFirstBytes) {
  EXPECT_EQ(sniff(std::string("PK\x03\x04", 4) + "rest"), FileFormat::Zip);
  EXPECT_EQ(sniff(std::string("PK\x05\x06", 4)), FileFormat::Zip);  // np.savez() of nothing
  EXPECT_EQ(sniff("\x93NUMPY\x01"), FileFormat::Npy);
  EXPECT_EQ(sniff("\x80\x02}q\x00"), FileFormat::Pickle);
  EXPECT_EQ(sniff("(dp0\n"), FileFormat::Pickle);  // protocol 0
  EXPECT_EQ(sniff("\xef\xbb\xbf \n{\"betas\": [1]}"), FileFormat::Json);
  EXPECT_EQ(sniff("[0.5, 1]"), FileFormat::Json);
  EXPECT_EQ(sniff("# obj\nv 0 0 0\nvt 0 1\n"), FileFormat::Text);
  EXPECT_EQ(sniff(std::string(4096, '\0')), FileFormat::Unknown);  // a sparse file's zeros
  EXPECT_EQ(sniff(std::string("glTF\x02\x00\x00\x00", 8)), FileFormat::Unknown);
  EXPECT_EQ(sniff(""), FileFormat::Unknown);
  EXPECT_NE(acceptedFormat(kUvObjInput, FileFormat::Json), nullptr);  // JSON is text
  EXPECT_EQ(acceptedFormat(kUvNpyInput, FileFormat::Text), nullptr);
}

class InputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "input_kind_test_" + std::to_string(::getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A sparse file of `size` bytes starting with `head` (zeros after it).
  std::string sparse(const std::string& name, const std::string& head, off_t size) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path, std::ios::binary) << head;
    EXPECT_EQ(::truncate(path.c_str(), size), 0);
    return path;
  }
  std::string dir_;
};

constexpr off_t k3GB = 3ll << 30;

// The reported case: a 3 GB sparse file as --uv / --betas-file / --motion.
// Refused at once, without charging (or reading) more than the sniffed head.
TEST_F(InputFiles, SparseFilesAreRefusedUnread) {
  const std::string zeros = sparse("uv.obj", "", k3GB);
  for (const InputKind* kind :
       {&kUvObjInput, &kUvNpyInput, &kBetasInput, &kModelInput, &kDmplInput, &kNpyInput}) {
    const uint64_t before = memoryCharged();
    Result<std::vector<uint8_t>> r = readFileBytes(zeros, *kind);
    ASSERT_FALSE(r.ok()) << kind->what;
    EXPECT_EQ(r.message().rfind(zeros + ": not a " + std::string(kind->what) + " (expected ", 0),
              0u)
        << r.message();
    EXPECT_NE(r.message().find("starts with '\\x00\\x00"), std::string::npos) << r.message();
    EXPECT_EQ(memoryCharged(), before);
    EXPECT_FALSE(checkInputFile(zeros, *kind).ok());
  }
  // A valid .npy header in front of the 3 GB: refused by the size bound.
  const std::string npy = sparse("big_uv.npy", "\x93NUMPY\x01\x00", k3GB);
  Result<std::vector<uint8_t>> r = readFileBytes(npy, kUvNpyInput);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), npy + ": 3.0 GiB is too large for a UV file in .npy (at most 256.0 MiB)");
  Result<Array> a = readNpyFile(npy);  // readNpyFile's own bound (betas' reader gets it too)
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.message().find("3.0 GiB is too large for a .npy file"), std::string::npos)
      << a.message();
  const std::string json = sparse("betas.json", "{\"betas\": [", k3GB);
  EXPECT_NE(
      readFileBytes(json, kBetasInput).message().find("is too large for a betas file in JSON"),
      std::string::npos);
  // Motions: unknown first bytes are the container sniffer's to name (it maps the
  // file and reads only a few pages); pickles and JSON are bounded.
  EXPECT_EQ(*checkInputFile(zeros, kMotionInput), FileFormat::Unknown);
  const std::string pickle = sparse("walk.pkl", "\x80\x04", k3GB);
  EXPECT_NE(checkInputFile(pickle, kMotionInput)
                .message()
                .find("3.0 GiB is too large for a motion file in .pkl (pickle) (at most 1.0 GiB)"),
            std::string::npos);
  const std::string motion = sparse("walk.json", "{\"poses\": [", 300 << 20);
  Result<FileFormat> f = checkInputFile(motion, kMotionInput);
  ASSERT_FALSE(f.ok());
  EXPECT_NE(
      f.message().find("300.0 MiB is too large for a motion file in JSON (at most 256.0 MiB)"),
      std::string::npos)
      << f.message();
}

TEST_F(InputFiles, FilesOfTheirKindAreRead) {
  const std::string obj = dir_ + "/uv.obj";
  std::ofstream(obj) << "v 0 0 0\nvt 0.5 0.5\nf 1/1 1/1 1/1\n";
  Result<std::vector<uint8_t>> r = readFileBytes(obj, kUvObjInput);
  ASSERT_TRUE(r.ok()) << r.message();
  EXPECT_EQ(r->size(), fs::file_size(obj));
  const std::string big = dir_ + "/big.obj";  // more than the 4 KiB head: read from its start
  std::ofstream(big) << std::string(100000, '#') << "\nvt 1 1\n";
  r = readFileBytes(big, kUvObjInput);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->size(), 100008u);
  EXPECT_EQ((*r)[0], '#');
  EXPECT_EQ(*checkInputFile(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz", kModelInput),
            FileFormat::Zip);
  const std::string empty = dir_ + "/empty.json";
  std::ofstream(empty) << "";
  EXPECT_EQ(readFileBytes(empty, kBetasInput).message(),
            empty + ": empty file; expected a betas file (.npy, .npz (zip) or JSON)");
}

// Pipes: a model (mapped) must be a regular file; other kinds read a pipe up
// to their bound, sniffing its first bytes as they arrive.
TEST_F(InputFiles, PipesAreBoundedOrRefused) {
  const std::string fifo = dir_ + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  Result<FileFormat> m = checkInputFile(fifo, kModelInput);  // no writer: must not hang
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.message(),
            fifo + ": not a regular file (a pipe); a model file must be a regular file");
  const InputKind small = {"test file", {{FileFormat::Text, 1000}}, true};
  for (size_t n : {500u, 5000u}) {
    std::thread writer([&] {
      const int fd = ::open(fifo.c_str(), O_WRONLY);
      const std::string text(n, 'x');
      EXPECT_EQ(::write(fd, text.data(), text.size()), static_cast<ssize_t>(n));
      ::close(fd);
    });
    Result<std::vector<uint8_t>> r = readFileBytes(fifo, small);
    writer.join();
    if (n == 500) {
      ASSERT_TRUE(r.ok()) << r.message();
      EXPECT_EQ(r->size(), 500u);
    } else {
      ASSERT_FALSE(r.ok());
      EXPECT_EQ(r.message(), fifo +
                                 ": more than that from a pipe is too large for a test file in "
                                 "text (at most 1000 bytes)");
    }
  }
  Result<std::vector<uint8_t>> dev = readFileBytes("/dev/zero", kBetasInput);
  ASSERT_FALSE(dev.ok());
  EXPECT_EQ(dev.message(), "/dev/zero: not a regular file (a character device)");
}

}  // namespace
}  // namespace smpl
