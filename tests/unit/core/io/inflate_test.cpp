// zlib and gzip streams of unknown size (core/io/inflate.h): round trips
// against zlib's own deflate, truncation and corruption, and a bomb that
// must end with the memory budget's error rather than an allocation.
#include "core/io/inflate.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <string>
#include <vector>

namespace smpl {
namespace {

// zlib's deflate of `in`: windowBits 15 (zlib) or 31 (gzip).
std::vector<uint8_t> deflateAll(const std::vector<uint8_t>& in, bool gzip) {
  z_stream zs{};
  EXPECT_EQ(deflateInit2(&zs, 6, Z_DEFLATED, gzip ? 31 : 15, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::vector<uint8_t> out(deflateBound(&zs, in.size()) + 64);
  zs.next_in = const_cast<Bytef*>(in.data());
  zs.avail_in = static_cast<uInt>(in.size());
  zs.next_out = out.data();
  zs.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&zs, Z_FINISH), Z_STREAM_END);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

std::vector<uint8_t> randomBytes(size_t n) {
  std::mt19937 rng(5);
  std::vector<uint8_t> v(n);
  for (auto& b : v) b = static_cast<uint8_t>(rng() % 7);  // compressible
  return v;
}

TEST(Inflate, ZlibAndGzipRoundTrip) {
  const std::vector<uint8_t> data = randomBytes(300000);
  for (bool gzip : {false, true}) {
    std::vector<uint8_t> z = deflateAll(data, gzip);
    z.insert(z.end(), {'t', 'a', 'i', 'l'});  // bytes after the stream are ignored
    Result<InflatedBytes> out =
        inflateStream(z.data(), z.size(), gzip ? StreamFormat::Gzip : StreamFormat::Zlib, "x");
    ASSERT_TRUE(out.ok()) << out.message();
    EXPECT_EQ(out->data.toVector(), data);
    EXPECT_GE(out->charge.bytes(), data.size());
  }
  std::vector<uint8_t> nothing = deflateAll({}, false);
  Result<InflatedBytes> empty =
      inflateStream(nothing.data(), nothing.size(), StreamFormat::Zlib, "x");
  ASSERT_TRUE(empty.ok()) << empty.message();
  EXPECT_TRUE(empty->data.empty());
}

TEST(Inflate, TruncatedAndCorruptStreamsAreErrors) {
  const std::vector<uint8_t> z = deflateAll(randomBytes(5000), false);
  for (size_t n = 0; n < z.size(); ++n) {
    Result<InflatedBytes> r = inflateStream(z.data(), n, StreamFormat::Zlib, "x.z");
    ASSERT_FALSE(r.ok()) << n;
    ASSERT_EQ(r.message().rfind("x.z: ", 0), 0u) << r.message();
  }
  Result<InflatedBytes> cut = inflateStream(z.data(), z.size() / 2, StreamFormat::Zlib, "x.z");
  EXPECT_EQ(cut.message().rfind("x.z: truncated zlib data", 0), 0u) << cut.message();
  std::vector<uint8_t> bad = z;
  bad[0] = 0x79;  // not a zlib header
  Result<InflatedBytes> corrupt = inflateStream(bad.data(), bad.size(), StreamFormat::Zlib, "x.z");
  ASSERT_FALSE(corrupt.ok());
  EXPECT_EQ(corrupt.message().rfind("x.z: corrupt zlib data (", 0), 0u) << corrupt.message();
  // The gzip reader refuses zlib data and the other way round.
  EXPECT_FALSE(inflateStream(z.data(), z.size(), StreamFormat::Gzip, "x.gz").ok());
}

TEST(Inflate, ABombEndsWithTheBudgetOrTheCap) {
  const std::vector<uint8_t> zeros(64u << 20, 0);
  const std::vector<uint8_t> bomb = deflateAll(zeros, false);  // about 64 KiB
  ASSERT_LT(bomb.size(), 100000u);
  const uint64_t before = memoryCharged();
  setMemoryLimit(16ull << 20);
  Result<InflatedBytes> r = inflateStream(bomb.data(), bomb.size(), StreamFormat::Zlib, "b.z");
  setMemoryLimit(0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message().rfind("b.z: inflating the zlib stream would need ", 0), 0u) << r.message();
  EXPECT_NE(r.message().find("set --memory-limit"), std::string::npos);
  EXPECT_EQ(memoryCharged(), before);
  Result<InflatedBytes> capped =
      inflateStream(bomb.data(), bomb.size(), StreamFormat::Zlib, "b.z", 1u << 20);
  ASSERT_FALSE(capped.ok());
  EXPECT_EQ(capped.message(), "b.z: the zlib stream inflates to more than 1.0 MiB");
}

}  // namespace
}  // namespace smpl
