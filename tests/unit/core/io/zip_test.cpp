// Tests for the zip reader. Archives written by numpy / Python's zipfile come
// from tests/fixtures/make_npy_cases.py; hostile ones are assembled here with
// a tiny writer and then patched field by field (offsets per APPNOTE.TXT).
#include "core/io/zip.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::readAll;

const std::string kCases = std::string(SMPL_FIXTURE_DIR) + "/npy_cases/";

void put16(std::string& s, size_t at, uint32_t v) {
  s[at] = static_cast<char>(v & 0xff);
  s[at + 1] = static_cast<char>((v >> 8) & 0xff);
}
void put32(std::string& s, size_t at, uint32_t v) {
  put16(s, at, v & 0xffff);
  put16(s, at + 2, v >> 16);
}
std::string le16(uint32_t v) {
  std::string s(2, '\0');
  put16(s, 0, v);
  return s;
}
std::string le32(uint32_t v) {
  std::string s(4, '\0');
  put32(s, 0, v);
  return s;
}

std::string rawDeflate(const std::string& in) {
  z_stream zs{};
  EXPECT_EQ(deflateInit2(&zs, 6, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&zs, in.size()), '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  zs.avail_in = static_cast<uInt>(in.size());
  zs.next_out = reinterpret_cast<Bytef*>(&out[0]);
  zs.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&zs, Z_FINISH), Z_STREAM_END);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

uint32_t crcOf(const std::string& s) {
  return static_cast<uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(s.data()), static_cast<uInt>(s.size())));
}

struct TestEntry {
  std::string name, data;
  bool deflate = false;
};

// A plain (non-zip64) archive plus the offsets tests patch.
struct Built {
  std::string bytes;
  std::vector<size_t> local, central, data;
  size_t eocd = 0;
};

Built buildZip(const std::vector<TestEntry>& entries, const std::string& comment = "") {
  Built b;
  std::string cd;
  for (const TestEntry& e : entries) {
    const std::string payload = e.deflate ? rawDeflate(e.data) : e.data;
    const std::string common = le16(20) + le16(0) + le16(e.deflate ? 8 : 0) + le16(0) + le16(0x21) +
                               le32(crcOf(e.data)) + le32(static_cast<uint32_t>(payload.size())) +
                               le32(static_cast<uint32_t>(e.data.size())) +
                               le16(static_cast<uint32_t>(e.name.size())) + le16(0);
    b.central.push_back(cd.size());
    cd += le32(0x02014b50) + le16(20) + common + le16(0) + le16(0) + le16(0) + le32(0) +
          le32(static_cast<uint32_t>(b.bytes.size())) + e.name;
    b.local.push_back(b.bytes.size());
    b.bytes += le32(0x04034b50) + common + e.name;
    b.data.push_back(b.bytes.size());
    b.bytes += payload;
  }
  const size_t cd_offset = b.bytes.size();
  for (size_t& c : b.central) c += cd_offset;
  b.bytes += cd;
  b.eocd = b.bytes.size();
  const uint32_t n = static_cast<uint32_t>(entries.size());
  b.bytes += le32(0x06054b50) + le16(0) + le16(0) + le16(n) + le16(n) +
             le32(static_cast<uint32_t>(cd.size())) + le32(static_cast<uint32_t>(cd_offset)) +
             le16(static_cast<uint32_t>(comment.size())) + comment;
  return b;
}

Result<std::vector<ZipEntry>> read(const std::string& bytes,
                                   const ZipLimits& limits = ZipLimits()) {
  return readZip(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "model.npz", limits);
}

void expectError(const std::string& bytes, const std::string& keyword,
                 const ZipLimits& limits = ZipLimits()) {
  Result<std::vector<ZipEntry>> r = read(bytes, limits);
  ASSERT_FALSE(r.ok()) << "accepted; expected '" << keyword << "'";
  EXPECT_EQ(r.message().rfind("model.npz", 0), 0u) << r.message();
  EXPECT_NE(r.message().find(keyword), std::string::npos) << r.message();
}

const std::vector<TestEntry> kTwo = {{"a.npy", "hello hello hello hello", false},
                                     {"b.npy", std::string(1000, 'x') + "tail", true}};

TEST(Zip, ReadsStoredAndDeflatedEntries) {
  Built b = buildZip(kTwo, "a comment");
  Result<std::vector<ZipEntry>> r = read(b.bytes);
  ASSERT_TRUE(r.ok()) << r.message();
  ASSERT_EQ(r->size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ((*r)[i].name, kTwo[i].name);
    EXPECT_EQ(std::string((*r)[i].data.begin(), (*r)[i].data.end()), kTwo[i].data);
  }
}

TEST(Zip, EmptyArchiveHasNoEntries) {
  Result<std::vector<ZipEntry>> r = read(buildZip({}).bytes);
  ASSERT_TRUE(r.ok()) << r.message();
  EXPECT_TRUE(r->empty());
}

TEST(Zip, ReadsArchivesWrittenByNumpyAndPython) {
  nlohmann::json expected = nlohmann::json::parse(readAll(kCases + "expected_npz.json"));
  for (const char* file : {"stored.npz", "deflated.npz", "forced_zip64.npz", "full_zip64.npz"}) {
    SCOPED_TRACE(file);
    Result<std::vector<ZipEntry>> r = read(readAll(kCases + file));
    ASSERT_TRUE(r.ok()) << r.message();
    std::set<std::string> names, want;
    for (const ZipEntry& e : *r) {
      names.insert(e.name);
      EXPECT_EQ(std::string(e.data.begin(), e.data.begin() + 6), "\x93NUMPY");
    }
    for (auto it = expected[file].begin(); it != expected[file].end(); ++it)
      want.insert(it.key() + ".npy");
    EXPECT_EQ(names, want);
  }
}

TEST(Zip, EveryTruncationIsAnError) {
  for (const char* file : {"deflated.npz", "full_zip64.npz"}) {
    const std::string full = readAll(kCases + file);
    for (size_t len = 0; len < full.size(); ++len) {
      Result<std::vector<ZipEntry>> r = read(full.substr(0, len));
      ASSERT_FALSE(r.ok()) << file << " cut at " << len;
      EXPECT_EQ(r.message().rfind("model.npz", 0), 0u) << r.message();
    }
  }
}

TEST(Zip, NotAZip) {
  expectError("", "not a zip archive");
  expectError(std::string(100, 'x'), "no end of central directory");
}

TEST(Zip, DeclaredSizesOverTheLimitFailBeforeReading) {
  ZipLimits limits;
  limits.max_total_uncompressed = 1000;  // the two entries hold 1027 bytes
  expectError(buildZip(kTwo).bytes,
              "declared uncompressed size exceeds the limit of 1000 bytes at 'b.npy'", limits);
  limits = ZipLimits();
  limits.max_entries = 1;
  expectError(buildZip(kTwo).bytes, "2 entries exceed the limit of 1", limits);
}

TEST(Zip, ImpossibleDeclaredSizeIsNotAllocated) {
  Built b = buildZip(kTwo);
  put32(b.bytes, b.central[1] + 24, 0xfffffff0u);  // 4 GiB from a few bytes of deflate
  expectError(b.bytes, "is impossible for");
}

TEST(Zip, DeflateBombStopsAtTheDeclaredSize) {
  Built b = buildZip({{"bomb.npy", std::string(20 << 20, '\0'), true}});
  ASSERT_LT(b.bytes.size(), 40000u);  // 20 MiB of zeros deflate to ~20 KiB
  put32(b.bytes, b.central[0] + 24, 1 << 20);
  expectError(b.bytes,
              "model.npz/bomb.npy: deflate data inflates to more than the declared 1048576 bytes");
}

TEST(Zip, ShorterDeflateOutputThanDeclaredIsAnError) {
  Built b = buildZip(kTwo);
  put32(b.bytes, b.central[1] + 24, 2000);
  expectError(b.bytes, "model.npz/b.npy: deflate data inflates to 1004 bytes; declared 2000");
}

TEST(Zip, CorruptDeflateStream) {
  Built b = buildZip(kTwo);
  b.bytes[b.data[1]] = '\xff';  // block type 3 is reserved
  expectError(b.bytes, "model.npz/b.npy: corrupt deflate data");
  Built cut = buildZip(kTwo);
  const uint32_t csize =
      static_cast<uint32_t>(cut.central[0] - cut.data[1]);  // the stream ends where the cd starts
  put32(cut.bytes, cut.central[1] + 20, csize - 3);
  put32(cut.bytes, cut.local[1] + 18, csize - 3);
  expectError(cut.bytes, "model.npz/b.npy: truncated deflate data");
}

TEST(Zip, CrcMismatch) {
  Built b = buildZip(kTwo);
  b.bytes[b.data[0]] ^= 1;
  expectError(b.bytes, "model.npz/a.npy: CRC mismatch: expected 0x");
  Built d = buildZip(kTwo);
  put32(d.bytes, d.central[1] + 16, 0x12345678);
  expectError(d.bytes, "model.npz/b.npy: CRC mismatch: expected 0x12345678, found 0x");
}

TEST(Zip, EntryOffsetsOutOfRange) {
  Built b = buildZip(kTwo);
  put32(b.bytes, b.central[1] + 42, 0x7fffffff);
  expectError(b.bytes, "model.npz/b.npy: local header offset 2147483647 is out of range");
  Built c = buildZip(kTwo);
  put32(c.bytes, c.central[0] + 20, 1u << 20);  // stored sizes too large for the file
  put32(c.bytes, c.central[0] + 24, 1u << 20);
  expectError(c.bytes, "model.npz/a.npy: entry data (1048576 bytes");
  Built d = buildZip(kTwo);
  put32(d.bytes, d.eocd + 16, 0x10000);
  expectError(d.bytes, "central directory (offset 65536");
}

TEST(Zip, HeadersThatDisagree) {
  Built b = buildZip(kTwo);
  b.bytes[b.local[1] + 30] = 'c';  // local name "c.npy"
  expectError(b.bytes, "model.npz/b.npy: local header disagrees");
  Built s = buildZip(kTwo);
  put32(s.bytes, s.central[0] + 24, 5);
  expectError(s.bytes, "model.npz/a.npy: stored entry sizes disagree");
  Built n = buildZip(kTwo);
  put16(n.bytes, n.eocd + 8, 200);
  put16(n.bytes, n.eocd + 10, 200);
  expectError(n.bytes, "cannot hold 200 entries");
  Built m = buildZip(kTwo);
  put16(m.bytes, m.eocd + 4, 1);
  expectError(m.bytes, "multi-disk");
  Built z = buildZip(kTwo);
  put32(z.bytes, z.eocd + 16, 0xffffffffu);
  expectError(z.bytes, "zip64 end of central directory locator missing");
}

TEST(Zip, EncryptionAndOtherMethodsAreRefused) {
  Built e = buildZip(kTwo);
  put16(e.bytes, e.central[0] + 8, 1);
  expectError(e.bytes, "model.npz/a.npy: encrypted zip entries are not supported");
  Built m = buildZip(kTwo);
  put16(m.bytes, m.central[1] + 10, 12);
  expectError(m.bytes, "model.npz/b.npy: unsupported compression method 12");
}

TEST(Zip, Zip64RecordOffsetOutOfRange) {
  std::string full = readAll(kCases + "full_zip64.npz");
  ASSERT_GT(full.size(), 42u);
  const size_t locator = full.size() - 22 - 20;
  ASSERT_EQ(full.substr(locator, 4), std::string("PK\x06\x07", 4));
  put32(full, locator + 8, 0x7ffffff0u);
  expectError(full, "bad zip64 end of central directory record offset");
}

// viewZipMember (the model loader's path): a stored member is the archive's
// own bytes (no copy), a deflated one is inflated; both CRC-checked and
// bounded like extractZipMember.
Result<ZipBytes> view(const std::string& bytes, size_t index,
                      const ZipLimits& limits = ZipLimits()) {
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  Result<std::vector<ZipMember>> members = listZip(data, bytes.size(), "model.npz");
  if (!members) return members.error();
  return viewZipMember(data, bytes.size(), (*members)[index], "model.npz", limits);
}

TEST(Zip, ViewedMembersAreTheArchiveBytesOrInflated) {
  Built b = buildZip(kTwo);
  Result<ZipBytes> stored = view(b.bytes, 0);
  ASSERT_TRUE(stored.ok()) << stored.message();
  EXPECT_EQ(stored->data, reinterpret_cast<const uint8_t*>(b.bytes.data()) + b.data[0]);
  EXPECT_EQ(stored->owned, nullptr);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(stored->data), stored->size), kTwo[0].data);
  Result<ZipBytes> inflated = view(b.bytes, 1);
  ASSERT_TRUE(inflated.ok()) << inflated.message();
  EXPECT_EQ(inflated->data, inflated->owned.get());
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(inflated->data), inflated->size),
            kTwo[1].data);
}

TEST(Zip, ViewedMembersAreCrcCheckedAndBounded) {
  Built b = buildZip(kTwo);
  b.bytes[b.data[0]] ^= 1;
  Result<ZipBytes> stored = view(b.bytes, 0);
  ASSERT_FALSE(stored.ok());
  EXPECT_NE(stored.message().find("model.npz/a.npy: CRC mismatch: expected 0x"), std::string::npos)
      << stored.message();
  Built d = buildZip(kTwo);
  put32(d.bytes, d.central[1] + 16, 0x12345678);
  Result<ZipBytes> inflated = view(d.bytes, 1);
  ASSERT_FALSE(inflated.ok());
  EXPECT_NE(inflated.message().find("model.npz/b.npy: CRC mismatch: expected 0x12345678"),
            std::string::npos)
      << inflated.message();
  ZipLimits small;
  small.max_total_uncompressed = 100;
  Result<ZipBytes> big = view(buildZip(kTwo).bytes, 1, small);
  ASSERT_FALSE(big.ok());
  EXPECT_NE(big.message().find("exceeds the limit of 100 bytes"), std::string::npos)
      << big.message();
  Built cut = buildZip(kTwo);
  cut.bytes[cut.data[1]] = '\xff';  // block type 3 is reserved
  Result<ZipBytes> corrupt = view(cut.bytes, 1);
  ASSERT_FALSE(corrupt.ok());
  EXPECT_NE(corrupt.message().find("model.npz/b.npy: corrupt deflate data"), std::string::npos)
      << corrupt.message();
}

}  // namespace
}  // namespace smpl
