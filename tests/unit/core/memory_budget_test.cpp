// The process-wide memory budget: charges add up across objects and threads,
// are released with their owner, and every reader refuses before allocating.
#include "core/memory_budget.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <thread>
#include <vector>

#include "core/array.h"
#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/io/pickle/pickle.h"

namespace smpl {
namespace {

constexpr uint64_t kMiB = 1ull << 20;

// Restores the default limit after each test (the budget is process-wide).
class MemoryBudgetTest : public ::testing::Test {
 protected:
  void SetUp() override { setMemoryLimit(64 * kMiB); }
  void TearDown() override { setMemoryLimit(0); }
};

TEST_F(MemoryBudgetTest, ChargesAddUpAndAreReleasedWithTheirOwner) {
  const uint64_t base = memoryCharged();
  {
    MemoryCharge a, b;
    ASSERT_TRUE(a.add(40 * kMiB, "a.npz", "first"));
    EXPECT_EQ(memoryCharged(), base + 40 * kMiB);
    Status st = b.add(40 * kMiB, "b.npz", "'poses' as doubles");
    ASSERT_FALSE(st);  // 80 MiB > 64 MiB together, though each fits alone
    EXPECT_EQ(st.message(),
              "b.npz: 'poses' as doubles would need 80.0 MiB in total; the limit is 64.0 MiB, set "
              "--memory-limit");
    EXPECT_EQ(b.bytes(), 0u);
    a.release();
    EXPECT_TRUE(b.add(40 * kMiB, "b.npz", "second"));
  }
  EXPECT_EQ(memoryCharged(), base);
}

TEST_F(MemoryBudgetTest, CopiesChargeAgainAndMovesTransfer) {
  const uint64_t base = memoryCharged();
  Array a;
  ASSERT_TRUE(a.charge.add(10 * kMiB, "x", "y"));
  {
    Array copy = a;
    EXPECT_EQ(memoryCharged(), base + 20 * kMiB);
    Array moved = std::move(copy);
    EXPECT_EQ(memoryCharged(), base + 20 * kMiB);
  }
  EXPECT_EQ(memoryCharged(), base + 10 * kMiB);
  a = Array();
  EXPECT_EQ(memoryCharged(), base);
}

TEST_F(MemoryBudgetTest, ThreadsShareOneLimit) {
  const uint64_t base = memoryCharged();
  std::vector<MemoryCharge> charges(8);
  std::vector<int> ok(8, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] { ok[t] = charges[t].add(10 * kMiB, "job", "frames") ? 1 : 0; });
  for (auto& th : threads) th.join();
  int granted = 0;
  for (int v : ok) granted += v;
  EXPECT_EQ(granted, 6);  // 6 x 10 MiB fit in 64 MiB, the 7th would not
  EXPECT_EQ(memoryCharged(), base + 60 * kMiB);
}

TEST_F(MemoryBudgetTest, NpyArrayIsRefusedBeforeWideningToDoubles) {
  // 16M one-byte elements: 16 MiB of payload, 128 MiB as doubles.
  const size_t n = 16 * kMiB;
  std::string dict =
      "{'descr': '|u1', 'fortran_order': False, 'shape': (" + std::to_string(n) + ",), }";
  while ((10 + dict.size() + 1) % 64 != 0) dict += ' ';
  dict += '\n';
  std::string bytes = std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(dict.size() & 0xff) +
                      static_cast<char>(dict.size() >> 8) + dict + std::string(n, '\0');
  Result<Array> a =
      parseNpy(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "big.npy");
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.message().find("big.npy: the array (16777216,) as doubles would need 128.0 MiB"),
            std::string::npos)
      << a.message();
  setMemoryLimit(256 * kMiB);
  a = parseNpy(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "big.npy");
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_EQ(a->charge.bytes(), n * sizeof(double));
}

TEST_F(MemoryBudgetTest, PickleHeapUsesTheSameBudget) {
  // Protocol 4: {'a': b'<70 MiB>'} (BINBYTES8): the heap's copy alone exceeds the 64 MiB budget,
  // though PickleLimits (4 GiB) would allow it.
  std::string p =
      "\x80\x04}\x8c\x01"
      "a"
      "\x8e";
  const uint64_t n = 70 * kMiB;
  for (int i = 0; i < 8; ++i) p += static_cast<char>((n >> (8 * i)) & 0xff);
  p += std::string(n, 'x') + "s.";
  Result<ArrayDict> d = parsePickle(reinterpret_cast<const uint8_t*>(p.data()), p.size(), "m.pkl");
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.message().find("set --memory-limit"), std::string::npos) << d.message();
  EXPECT_EQ(d.message().rfind("m.pkl: ", 0), 0u) << d.message();
}

TEST_F(MemoryBudgetTest, DevicesAreRefusedAndEndlessPipesStopAtTheLimit) {
  Result<std::vector<uint8_t>> zero = readFileBytes("/dev/zero");
  ASSERT_FALSE(zero.ok());
  EXPECT_EQ(zero.message(), "/dev/zero: not a regular file (a character device)");
  // A pipe that never ends: the reader must stop with the budget's error.
  const std::string fifo = ::testing::TempDir() + "smpl_endless_fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ::signal(SIGPIPE, SIG_IGN);
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    std::vector<char> block(1 << 16, 'x');
    while (fd >= 0 && ::write(fd, block.data(), block.size()) > 0) {
    }
    if (fd >= 0) ::close(fd);
  });
  Result<std::vector<uint8_t>> endless = readFileBytes(fifo);
  writer.join();
  std::remove(fifo.c_str());
  ASSERT_FALSE(endless.ok());
  EXPECT_NE(endless.message().find("reading the file would need 128.0 MiB; the limit is 64.0 MiB"),
            std::string::npos)
      << endless.message();
}

TEST(MemorySize, ParsesSuffixesAndRefusesNonsense) {
  EXPECT_EQ(*parseMemorySize("512M"), 512 * kMiB);
  EXPECT_EQ(*parseMemorySize("4G"), 4096 * kMiB);
  EXPECT_EQ(*parseMemorySize("1.5GiB"), 1536 * kMiB);
  EXPECT_EQ(*parseMemorySize("2g"), 2048 * kMiB);
  EXPECT_EQ(*parseMemorySize("100000000"), 100000000u);
  for (const char* bad : {"", "M", "12X", "-1G", "1M", "nanG", "1e300", "4GG", "5P"})
    EXPECT_FALSE(parseMemorySize(bad).ok()) << bad;
}

TEST(MemorySize, DefaultIsAtMostEightGiB) {
  EXPECT_LE(defaultMemoryLimit(), 8ull << 30);
  EXPECT_GT(defaultMemoryLimit(), 0u);
  EXPECT_EQ(formatBytes(3865470566ull), "3.6 GiB");
  EXPECT_EQ(formatBytes(512), "512 bytes");
}

}  // namespace
}  // namespace smpl
