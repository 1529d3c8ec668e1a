#include "cli/batch_shard.h"

#include <gtest/gtest.h>

#include <map>

#include "cli/manifest.h"
#include "cli/sha256.h"

namespace smpl {
namespace {

TEST(BatchShard, EveryMotionInExactlyOneShardInSortedOrder) {
  std::vector<std::string> files;
  for (const char* name : {"d/z.npz", "a.npz", "c.smpl", "b/x.npz", "b/a.pkl", "e.json", "f.npz"})
    files.push_back(std::string("/data/amass/") + name);
  std::map<std::string, int> seen;
  for (int n : {1, 2, 3, 7, 10}) {
    seen.clear();
    size_t largest = 0, smallest = files.size();
    for (int i = 0; i < n; ++i) {
      std::vector<std::string> share = shardMotions(files, "/data/amass", i, n);
      largest = std::max(largest, share.size());
      smallest = std::min(smallest, share.size());
      for (const std::string& p : share) ++seen[p];
    }
    EXPECT_EQ(seen.size(), files.size()) << n;
    for (const auto& [path, count] : seen)
      EXPECT_EQ(count, 1) << path << " in " << count << " of " << n << " shards";
    EXPECT_LE(largest - smallest, 1u) << n;
  }
  // Sorted relative paths a.npz b/a.pkl b/x.npz c.smpl d/z.npz e.json f.npz; shard 1 of 3 holds
  // positions 1, 4.
  std::vector<std::string> one = shardMotions(files, "/data/amass", 1, 3);
  ASSERT_EQ(one.size(), 2u);
  EXPECT_EQ(one[0], "/data/amass/b/a.pkl");
  EXPECT_EQ(one[1], "/data/amass/d/z.npz");
}

TEST(Sha256, KnownVectors) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256Hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Manifest, OneJsonObjectPerLine) {
  ManifestEntry e;
  e.input = "in/walk.npz";
  e.output = "out/walk.glb";
  e.status = "converted";
  e.bytes = 12;
  e.sha256 = "ab";
  e.seconds = 0.25;
  EXPECT_EQ(manifestLine(e),
            R"({"input":"in/walk.npz","output":"out/walk.glb","bytes":12,"sha256":"ab",)"
            R"("seconds":0.25,"status":"converted"})");
  ManifestEntry skipped;
  skipped.input = "in/shape.npz";
  skipped.status = "skipped";
  skipped.message = "no pose data";
  EXPECT_EQ(manifestLine(skipped),
            R"({"input":"in/shape.npz","output":null,"bytes":null,"sha256":null,)"
            R"("seconds":0.0,"status":"skipped","reason":"no pose data"})");
}

}  // namespace
}  // namespace smpl
