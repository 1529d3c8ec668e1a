// Byte-exact goldens for the binary FBX encoder. The expected bytes are
// written out by hand from the format description (record header, name,
// properties, null records, footer), not taken from the encoder's output.
#include "writers/fbx/fbx_encoder.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <string>

namespace smpl {
namespace {

std::string bytes(std::initializer_list<int> values) {
  std::string s;
  for (int v : values) s.push_back(static_cast<char>(v));
  return s;
}

const std::string kMagic = std::string("Kaydara FBX Binary  ") + bytes({0x00, 0x1a, 0x00});
const std::string kFooterId = bytes({0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66, 0xb1, 0x76,
                                     0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e});
const std::string kFooterMagic = bytes({0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e, 0xec, 0xe9,
                                        0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b});

// Tree: A(I 1) { B(S "hi") }, C (no properties, no children).
std::vector<FbxNode> tinyTree() {
  std::vector<FbxNode> top(2);
  top[0].name = "A";
  top[0].addInt32(1);
  top[0].add("B").addString("hi");
  top[1].name = "C";
  return top;
}

TEST(FbxEncoder, Version7400GoldenBytes) {
  std::string expected = kMagic + bytes({0xe8, 0x1c, 0x00, 0x00});  // 7400; offset 27
  // A @27: end 80, 1 property, 5 property bytes, name "A", I 1
  expected += bytes({80, 0, 0, 0, 1, 0, 0, 0, 5, 0, 0, 0, 1, 'A', 'I', 1, 0, 0, 0});
  // B @46: end 67, 1 property, 7 property bytes, name "B", S len 2 "hi"; no null record
  expected += bytes({67, 0, 0, 0, 1, 0, 0, 0, 7, 0, 0, 0, 1, 'B', 'S', 2, 0, 0, 0, 'h', 'i'});
  expected += std::string(13, '\0');  // A's nested-block null record, @67..80
  // C @80: end 107, no properties: header, name, then a null record
  expected += bytes({107, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 'C'}) + std::string(13, '\0');
  expected += std::string(13, '\0');  // end of top level, @107..120
  expected += kFooterId;              // @120..136
  expected += std::string(4, '\0');   // @140
  expected += std::string(4, '\0');   // padding to 144
  expected += bytes({0xe8, 0x1c, 0x00, 0x00}) + std::string(120, '\0') + kFooterMagic;
  ASSERT_EQ(expected.size(), 284u);

  Result<std::string> out = encodeFbx(tinyTree(), 7400);
  ASSERT_TRUE(out.ok()) << out.message();
  EXPECT_EQ(*out, expected);
}

TEST(FbxEncoder, Version7500UsesWideHeadersAndNullRecords) {
  std::vector<FbxNode> top(1);
  top[0].name = "C";
  std::string expected = kMagic + bytes({0x4c, 0x1d, 0x00, 0x00});  // 7500
  // C @27: 3 x uint64 header (end 78), name, 25-byte null record
  expected += bytes({78, 0, 0, 0, 0, 0, 0, 0}) + std::string(16, '\0') + bytes({1, 'C'});
  expected += std::string(25, '\0');
  expected += std::string(25, '\0');             // end of top level, @78..103
  expected += kFooterId + std::string(4, '\0');  // @123
  expected += std::string(5, '\0');              // padding to 128
  expected += bytes({0x4c, 0x1d, 0x00, 0x00}) + std::string(120, '\0') + kFooterMagic;
  ASSERT_EQ(expected.size(), 268u);

  Result<std::string> out = encodeFbx(top, 7500);
  ASSERT_TRUE(out.ok()) << out.message();
  EXPECT_EQ(*out, expected);
}

TEST(FbxEncoder, ScalarAndSmallArrayPayloads) {
  FbxNode n("N");
  n.addBool(true).addInt16(-2).addInt64(-3).addFloat(1.5f).addDouble(-0.25).addRaw("xy");
  n.addInt32Array({1, -1});
  ASSERT_EQ(n.properties.size(), 7u);
  EXPECT_EQ(n.properties[0].type, 'C');
  EXPECT_EQ(n.properties[0].payload, bytes({1}));
  EXPECT_EQ(n.properties[1].payload, bytes({0xfe, 0xff}));
  EXPECT_EQ(n.properties[2].payload, bytes({0xfd, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff}));
  EXPECT_EQ(n.properties[3].payload, bytes({0x00, 0x00, 0xc0, 0x3f}));        // 1.5f
  EXPECT_EQ(n.properties[4].payload, bytes({0, 0, 0, 0, 0, 0, 0xd0, 0xbf}));  // -0.25
  EXPECT_EQ(n.properties[5].type, 'R');
  EXPECT_EQ(n.properties[5].payload, bytes({2, 0, 0, 0, 'x', 'y'}));
  EXPECT_EQ(n.properties[6].type, 'i');
  // count 2, encoding 0, 8 bytes, then the values
  EXPECT_EQ(n.properties[6].payload,
            bytes({2, 0, 0, 0, 0, 0, 0, 0, 8, 0, 0, 0, 1, 0, 0, 0, 0xff, 0xff, 0xff, 0xff}));
}

TEST(FbxEncoder, LargeArraysAreZlibCompressed) {
  std::vector<double> values(100);
  for (size_t i = 0; i < values.size(); ++i) values[i] = 0.5 * double(i);
  std::vector<FbxNode> top(1, FbxNode("N"));
  top[0].addDoubleArray(values);
  // Compression happens in encodeFbx(): read the property back from the file.
  // Layout: 27-byte header, then node "N" (3 x uint32 header fields, name
  // length, name), then the type code 'd' and the payload.
  Result<std::string> file = encodeFbx(top, 7400);
  ASSERT_TRUE(file.ok()) << file.message();
  const size_t at = 27 + 12 + 1 + 1;
  ASSERT_EQ((*file)[at], 'd');
  uint32_t end_offset, payload_length;
  std::memcpy(&end_offset, file->data() + 27, 4);
  std::memcpy(&payload_length, file->data() + at + 1 + 8, 4);
  const std::string p = file->substr(at + 1, 12 + payload_length);
  EXPECT_EQ(end_offset, at + 1 + p.size());  // the node ends right after its one property
  uint32_t count, encoding, length;
  std::memcpy(&count, p.data(), 4);
  std::memcpy(&encoding, p.data() + 4, 4);
  std::memcpy(&length, p.data() + 8, 4);
  EXPECT_EQ(count, 100u);
  EXPECT_EQ(encoding, 1u);
  ASSERT_EQ(length, p.size() - 12);
  std::vector<double> back(100);
  uLongf size = sizeof(double) * 100;
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(back.data()), &size,
                       reinterpret_cast<const Bytef*>(p.data() + 12), length),
            Z_OK);
  EXPECT_EQ(size, sizeof(double) * 100);
  EXPECT_EQ(back, values);
}

// The single-array file of LargeArraysAreZlibCompressed at `level`: the
// property's payload (count, encoding, byte length, data).
std::string arrayPayload(const std::vector<double>& values, int level) {
  std::vector<FbxNode> top(1, FbxNode("N"));
  top[0].addDoubleArray(values);
  FbxEncodeOptions o;
  o.compress_level = level;
  Result<std::string> file = encodeFbx(top, 7400, o);
  EXPECT_TRUE(file.ok()) << file.message();
  if (!file) return "";
  const size_t at = 27 + 12 + 1 + 1;
  EXPECT_EQ((*file)[at], 'd');
  uint32_t payload_length;
  std::memcpy(&payload_length, file->data() + at + 1 + 8, 4);
  return file->substr(at + 1, 12 + payload_length);
}

TEST(FbxEncoder, LevelZeroStoresArraysUncompressed) {
  std::vector<double> values(100);
  for (size_t i = 0; i < values.size(); ++i) values[i] = 0.5 * double(i);
  const std::string p = arrayPayload(values, 0);
  uint32_t count, encoding, length;
  std::memcpy(&count, p.data(), 4);
  std::memcpy(&encoding, p.data() + 4, 4);
  std::memcpy(&length, p.data() + 8, 4);
  EXPECT_EQ(count, 100u);
  EXPECT_EQ(encoding, 0u);  // FBX array encoding 0: the raw little-endian values
  ASSERT_EQ(length, sizeof(double) * 100);
  ASSERT_EQ(p.size(), 12 + length);
  std::vector<double> back(100);
  std::memcpy(back.data(), p.data() + 12, length);
  EXPECT_EQ(back, values);
}

TEST(FbxEncoder, EveryLevelInflatesToTheSameValuesAndBadLevelsAreRefused) {
  std::vector<double> values(4000);
  for (size_t i = 0; i < values.size(); ++i) values[i] = std::sin(0.01 * double(i)) * (i % 7);
  for (int level : {1, 6, 12}) {
    const std::string p = arrayPayload(values, level);
    uint32_t encoding, length;
    std::memcpy(&encoding, p.data() + 4, 4);
    std::memcpy(&length, p.data() + 8, 4);
    EXPECT_EQ(encoding, 1u) << level;
    std::vector<double> back(values.size());
    uLongf size = sizeof(double) * values.size();
    ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(back.data()), &size,
                         reinterpret_cast<const Bytef*>(p.data() + 12), length),
              Z_OK)
        << level;
    EXPECT_EQ(back, values) << level;
  }
  std::vector<FbxNode> top(1, FbxNode("N"));
  for (int bad : {-1, 13}) {
    FbxEncodeOptions o;
    o.compress_level = bad;
    Result<std::string> out = encodeFbx(top, 7400, o);
    ASSERT_FALSE(out.ok()) << bad;
    EXPECT_NE(out.message().find("compression level"), std::string::npos) << out.message();
  }
}

// Arrays are compressed on several threads; which thread takes which array
// must never show in the bytes (every level, including stored).
TEST(FbxEncoder, BytesDoNotDependOnTheThreadCount) {
  std::vector<FbxNode> top(1, FbxNode("Objects"));
  for (int a = 0; a < 40; ++a) {
    std::vector<float> values(500 + 37 * a);
    for (size_t i = 0; i < values.size(); ++i)
      values[i] = float(std::sin(0.003 * double(i * (a + 1))));
    top[0].add("Shape" + std::to_string(a)).addFloatArray(values);
  }
  for (int level : {0, 1, 6}) {
    FbxEncodeOptions one;
    one.compress_level = level;
    one.threads = 1;
    Result<std::string> reference = encodeFbx(top, 7400, one);
    ASSERT_TRUE(reference.ok()) << reference.message();
    for (int threads : {2, 3, 8, 0}) {
      FbxEncodeOptions o = one;
      o.threads = threads;
      Result<std::string> out = encodeFbx(top, 7400, o);
      ASSERT_TRUE(out.ok()) << out.message();
      EXPECT_TRUE(*out == *reference) << "level " << level << ", " << threads << " threads";
    }
  }
}

// Nodes handed over (encodeFbx(std::move(top)): arrays freed once compressed,
// compressed arrays once written) give the bytes of the same nodes lent; a
// shared array (a clip's key times on every curve) is written at each node
// that has it, as the same array added to each would be: with long and short
// (not deferred) shared arrays, arrays with the same bytes and distinct ones,
// at every level and both versions. The handed-over nodes are gone.
TEST(FbxEncoder, HandedOverNodesAndSharedArraysGiveTheSameBytes) {
  for (size_t keys : {size_t(3000), size_t(5)}) {
    std::vector<int64_t> times(keys);
    for (size_t i = 0; i < keys; ++i) times[i] = int64_t(i) * 1539538600;
    auto build = [&](bool shared) {
      std::vector<FbxNode> top(1, FbxNode("Objects"));
      const FbxProperty key_times = fbxSharedInt64Array(times);
      for (int c = 0; c < 12; ++c) {
        FbxNode& curve = top[0].add("AnimationCurve");
        if (shared)
          curve.add("KeyTime").addShared(key_times);
        else
          curve.add("KeyTime").addInt64Array(times);
        std::vector<float> values(keys, 0.0f);  // every fourth curve: the same zeros
        if (c % 4 != 0)
          for (size_t i = 0; i < keys; ++i) values[i] = float(std::sin(0.01 * double(i * c)));
        curve.add("KeyValueFloat").addFloatArray(values);
      }
      return top;
    };
    for (uint32_t version : {7400u, 7500u})
      for (int level : {0, 1, 6}) {
        FbxEncodeOptions o;
        o.compress_level = level;
        const std::vector<FbxNode> lent = build(false);
        Result<std::string> reference = encodeFbx(lent, version, o);
        const std::vector<FbxNode> shared = build(true);
        Result<std::string> lent_shared = encodeFbx(shared, version, o);
        std::vector<FbxNode> handed = build(true);
        Result<std::string> out = encodeFbx(std::move(handed), version, o);
        ASSERT_TRUE(reference && lent_shared && out) << out.message();
        EXPECT_TRUE(*lent_shared == *reference) << keys << " keys, level " << level;
        EXPECT_TRUE(*out == *reference) << keys << " keys, level " << level << ", " << version;
        EXPECT_TRUE(handed.empty());
      }
  }
}

TEST(FbxEncoder, RejectsBadNamesAndVersions) {
  std::vector<FbxNode> top(1);
  top[0].name = std::string(256, 'x');
  EXPECT_FALSE(encodeFbx(top, 7400).ok());
  top[0].name = "";
  EXPECT_FALSE(encodeFbx(top, 7400).ok());
  top[0].name = "ok";
  EXPECT_FALSE(encodeFbx(top, 6100).ok());
  EXPECT_TRUE(encodeFbx(top, 7400).ok());
}

}  // namespace
}  // namespace smpl
