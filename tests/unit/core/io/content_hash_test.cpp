// ContentHash: independent of how the bytes are split, sensitive to every
// byte and to string boundaries; hashFileContent agrees with the bytes.
#include "core/io/content_hash.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace smpl {
namespace {

TEST(ContentHash, SplitDoesNotMatter) {
  std::string bytes(1000, '\0');
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 37 + 11);
  ContentHash whole;
  whole.add(bytes.data(), bytes.size());
  for (size_t cut : {size_t{1}, size_t{3}, size_t{8}, size_t{13}, size_t{999}}) {
    ContentHash parts;
    parts.add(bytes.data(), cut);
    parts.add(bytes.data() + cut, bytes.size() - cut);
    EXPECT_EQ(parts.value(), whole.value()) << "cut at " << cut;
  }
}

TEST(ContentHash, EveryByteAndLengthMatters) {
  std::string bytes(64, 'a');
  ContentHash base;
  base.add(bytes.data(), bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string changed = bytes;
    changed[i] = 'b';
    ContentHash h;
    h.add(changed.data(), changed.size());
    EXPECT_NE(h.value(), base.value()) << "byte " << i;
  }
  ContentHash shorter, zero_padded;
  shorter.add(bytes.data(), 63);
  std::string with_zero = bytes.substr(0, 63) + std::string(1, '\0');
  zero_padded.add(with_zero.data(), with_zero.size());
  EXPECT_NE(shorter.value(), zero_padded.value());
  ContentHash ab_c, a_bc;
  ab_c.add(std::string("ab"));
  ab_c.add(std::string("c"));
  a_bc.add(std::string("a"));
  a_bc.add(std::string("bc"));
  EXPECT_NE(ab_c.value(), a_bc.value());
  EXPECT_EQ(base.hex().size(), 16u);
}

TEST(ContentHash, FileMatchesBytes) {
  const std::string path = ::testing::TempDir() + "content_hash_" + std::to_string(::getpid());
  std::string bytes(3 << 20, '\0');  // several read chunks
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 131) >> 3);
  std::ofstream(path, std::ios::binary) << bytes;
  ContentHash h;
  h.add(bytes.data(), bytes.size());
  Result<uint64_t> file = hashFileContent(path);
  std::remove(path.c_str());
  ASSERT_TRUE(file.ok()) << file.message();
  EXPECT_EQ(*file, h.value());
  EXPECT_FALSE(hashFileContent(path).ok());
}

}  // namespace
}  // namespace smpl
