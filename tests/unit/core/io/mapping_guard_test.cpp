// A mapped input that shrinks while it is read (another process truncates or
// rewrites it) gives the reader zeros and then the error naming the file,
// never SIGBUS (core/io/mapping_guard.h); faults elsewhere still kill.
#include "core/io/mapping_guard.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "core/io/mapped_file.h"
#include "core/io/npz.h"

namespace smpl {
namespace {

namespace fs = std::filesystem;

class MappingGuardTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "mapping_guard_test_" + std::to_string(::getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name, size_t size) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path, std::ios::binary) << std::string(size, 'x');
    return path;
  }
  std::string dir_;
};

uint64_t sum(const uint8_t* data, size_t size) {
  uint64_t s = 0;
  for (size_t i = 0; i < size; ++i) s += data[i];
  return s;
}

TEST_F(MappingGuardTest, ShrunkMappedFileReadsZerosAndReportsTheFile) {
  const std::string path = file("model.pkl", 1 << 20);
  Result<MappedFile> f = MappedFile::open(path);
  ASSERT_TRUE(f.ok()) << f.message();
  EXPECT_TRUE(f->intact().ok());
  EXPECT_EQ(sum(f->data(), 8192), 8192u * 'x');
  ASSERT_EQ(::truncate(path.c_str(), 4096), 0);  // keeps the first page
  const uint64_t s = sum(f->data(), f->size());  // faults past 4096: zeros, no SIGBUS
  EXPECT_EQ(s, 4096u * 'x');
  Status st = f->intact();
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message().rfind(path + ": cannot read: the file shrank while it was being read", 0),
            0u)
      << st.message();
}

TEST_F(MappingGuardTest, ShrunkNpzGivesTheErrorNamingTheArchive) {
  const std::string path = dir_ + "/smpl_small.npz";
  fs::copy_file(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz", path);
  Result<NpzArchive> npz = NpzArchive::open(path);
  ASSERT_TRUE(npz.ok()) << npz.message();
  ASSERT_TRUE(npz->get("v_template").ok());
  ASSERT_EQ(::truncate(path.c_str(), 0), 0);
  for (const char* key : {"shapedirs", "weights"}) {  // stored members, read in place
    Result<Array> a = npz->get(key);
    ASSERT_FALSE(a.ok()) << key;
    EXPECT_NE(a.message().find(path + ": cannot read: the file shrank"), std::string::npos)
        << a.message();
  }
  EXPECT_FALSE(npz->intact().ok());
}

// Several mappings at once (batch jobs on threads): each is told apart.
TEST_F(MappingGuardTest, EachMappingIsToldApart) {
  const std::string a = file("a.pkl", 256 << 10), b = file("b.pkl", 256 << 10);
  Result<MappedFile> fa = MappedFile::open(a), fb = MappedFile::open(b);
  ASSERT_TRUE(fa.ok() && fb.ok());
  ASSERT_EQ(::truncate(a.c_str(), 0), 0);
  uint64_t zeros = 1;
  std::thread reader([&] { zeros = sum(fa->data(), fa->size()); });
  EXPECT_EQ(sum(fb->data(), fb->size()), (256u << 10) * 'x');
  reader.join();
  EXPECT_EQ(zeros, 0u);
  EXPECT_FALSE(fa->intact().ok());
  EXPECT_TRUE(fb->intact().ok());
  MappedFile moved = std::move(*fa);
  EXPECT_FALSE(moved.intact().ok());  // the mark moves with the mapping
}

// How a SIGBUS that is not ours ends the process: the handler installed before
// ours decides. Without one that is the default action (killed by SIGBUS);
// AddressSanitizer installs its own, which reports the fault and aborts.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SMPL_PREVIOUS_SIGBUS_HANDLER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SMPL_PREVIOUS_SIGBUS_HANDLER 1
#endif

bool diedOfForeignSigbus(int status) {
#ifdef SMPL_PREVIOUS_SIGBUS_HANDLER
  return !(WIFEXITED(status) && WEXITSTATUS(status) == 0);  // whatever it did, not survived
#else
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGBUS;
#endif
}

// Only registered mappings are covered: a SIGBUS anywhere else (a mapping of
// someone else's, a signal sent to the process) still ends it as before.
TEST_F(MappingGuardTest, OtherSigbusStillKills) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::string path = file("other.bin", 64 << 10);
  EXPECT_EXIT(
      {
        MappingGuard installed(path.data(), 1);  // installs the handler
        const int fd = ::open(path.c_str(), O_RDONLY);
        void* m = ::mmap(nullptr, 64 << 10, PROT_READ, MAP_PRIVATE, fd, 0);
        if (::truncate(path.c_str(), 0) != 0) ::_exit(1);
        volatile uint8_t byte = static_cast<const uint8_t*>(m)[32 << 10];
        (void)byte;
        ::_exit(0);
      },
      diedOfForeignSigbus, "");
  EXPECT_EXIT(
      {
        MappingGuard installed(path.data(), 1);
        ::raise(SIGBUS);
        ::_exit(0);
      },
      diedOfForeignSigbus, "");
}

TEST(MappingGuard, SlotsAreReleased) {
  std::vector<char> data(4096);
  for (int round = 0; round < 3; ++round) {
    std::vector<MappingGuard> guards;
    for (int i = 0; i < MappingGuard::kMaxWatched; ++i) guards.emplace_back(data.data(), 1);
    for (const MappingGuard& g : guards) EXPECT_TRUE(g.watching());
    EXPECT_FALSE(MappingGuard(data.data(), 1).watching());  // all slots taken: caller copies
  }
}

}  // namespace
}  // namespace smpl
