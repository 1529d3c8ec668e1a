// The USD writer's pieces: the text forms (usd_text.h), the .usdz archive
// (usdz_archive.h, read back by the project's zip reader core/io/zip.h and,
// in the usd.* tests, by Python's zipfile and tinyusdz) and the layer's
// structure and errors (usd_layer.h). What the layer means is checked
// against the model's math by an independent reader (tests/usd/).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "../../test_asset.h"
#include "core/io/zip.h"
#include "writers/usd/usd_layer.h"
#include "writers/usd/usd_text.h"
#include "writers/usd/usdz_archive.h"
#include "writers/writer.h"

namespace smpl {
namespace {

std::string floatText(float v) {
  std::string s;
  usd::appendFloat(s, v);
  return s;
}

TEST(UsdText, FloatsAreShortestAndReadBackExactly) {
  EXPECT_EQ(floatText(0.1f), "0.1");
  EXPECT_EQ(floatText(-0.0f), "0");
  EXPECT_EQ(floatText(1.0f), "1");
  EXPECT_EQ(floatText(-2.5e-8f), "-2.5e-08");
  std::mt19937 rng(7);
  std::uniform_int_distribution<uint32_t> bits;
  for (int i = 0; i < 20000; ++i) {
    uint32_t b = bits(rng);
    float v;
    std::memcpy(&v, &b, sizeof v);
    if (!std::isfinite(v)) continue;
    const std::string text = floatText(v);
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), v) << text;
    EXPECT_EQ(float(std::strtod(text.c_str(), nullptr)), v) << text;  // USD parses doubles
  }
}

TEST(UsdText, QuaternionsRealFirstAndMatricesRowVector) {
  std::string q;
  usd::appendQuat(q, Eigen::Quaternionf(0.5f, 0.25f, -0.125f, 1.0f));  // Eigen: (w, x, y, z)
  EXPECT_EQ(q, "(0.5, 0.25, -0.125, 1)");
  std::string m;
  usd::appendTranslationMatrix(m, Eigen::Vector3d(0.1, -2, 3.5));
  EXPECT_EQ(m, "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0.1, -2, 3.5, 1))");
}

TEST(UsdText, IdentifiersAndStrings) {
  EXPECT_TRUE(usd::isIdentifier("left_hip"));
  EXPECT_TRUE(usd::isIdentifier("_a1"));
  for (const char* bad : {"", "1a", "a b", "a/b", "a:b", "a.b", "h\xc3\xa9", "a\"b"})
    EXPECT_FALSE(usd::isIdentifier(bad)) << bad;
  EXPECT_EQ(usd::quoted("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\nd\\x01\"");
}

TEST(UsdzArchive, EveryFileStoredAt64ByteBoundaries) {
  for (size_t name_length = 1; name_length <= 70; ++name_length) {
    const std::vector<UsdzFile> files = {{std::string(name_length, 'a') + ".usda", "#usda 1.0\n"},
                                         {"b.png", std::string(name_length * 7, '\x89')}};
    Result<std::string> zip = usdzArchive(files);
    ASSERT_TRUE(zip.ok()) << zip.message();
    const auto* data = reinterpret_cast<const uint8_t*>(zip->data());
    Result<std::vector<ZipMember>> members = listZip(data, zip->size(), "t.usdz");
    ASSERT_TRUE(members.ok()) << members.message();
    ASSERT_EQ(members->size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
      const ZipMember& m = (*members)[i];
      EXPECT_EQ(m.name, files[i].name);
      EXPECT_EQ(m.method, 0) << "stored, not deflated";
      Result<ZipBytes> bytes = viewZipMember(data, zip->size(), m, "t.usdz");  // CRC-checked
      ASSERT_TRUE(bytes.ok()) << bytes.message();
      EXPECT_EQ(size_t(bytes->data - data) % 64, 0u) << m.name;
      EXPECT_EQ(std::string(reinterpret_cast<const char*>(bytes->data), bytes->size),
                files[i].bytes);
    }
  }
}

TEST(UsdzArchive, RefusesNamesItCannotStore) {
  EXPECT_FALSE(usdzArchive({{"", "x"}}).ok());
  Result<std::string> accented = usdzArchive({{"h\xc3\xa9.usda", "x"}});
  ASSERT_FALSE(accented.ok());
  EXPECT_NE(accented.message().find("not printable ASCII"), std::string::npos);
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(UsdLayer, SkeletonMeshAndOneTimeSamplePerFrame) {
  const Asset a = test::makeAsset({/*joints=*/5, /*vertices=*/8, 4, true, 2, /*frames=*/3});
  Result<std::string> text = usdaLayer(a);
  ASSERT_TRUE(text.ok()) << text.message();
  EXPECT_EQ(text->rfind("#usda 1.0\n", 0), 0u);
  EXPECT_NE(text->find("metersPerUnit = 1\n"), std::string::npos);
  EXPECT_NE(text->find("upAxis = \"Y\"\n"), std::string::npos);
  EXPECT_NE(text->find("timeCodesPerSecond = 30\n"), std::string::npos);
  EXPECT_NE(text->find("endTimeCode = 2\n"), std::string::npos);
  // binary tree p(k) = (k - 1) / 2: joint 4's path is pelvis/joint_1/joint_4
  EXPECT_NE(text->find("uniform token[] joints = [\"pelvis\", \"pelvis/joint_1\", "
                       "\"pelvis/joint_2\", \"pelvis/joint_1/joint_3\", "
                       "\"pelvis/joint_1/joint_4\"]"),
            std::string::npos);
  std::string first = "                0: [";
  usd::appendQuat(first, a.animations[0].rotations[0][0]);
  EXPECT_NE(text->find(first), std::string::npos) << first;
  EXPECT_EQ(count(*text, "                2: ["), 3u);  // rotations, translations, weights
  EXPECT_EQ(count(*text, "def BlendShape "), 2u);
  EXPECT_NE(text->find("elementSize = 4"), std::string::npos);
  EXPECT_EQ(*usdaLayer(a), *text);  // same asset, same bytes
}

TEST(UsdLayer, WithoutAClipTheRestPoseIsTheDefault) {
  Asset a = test::makeAsset({3, 6, 2, false, 1, 0});
  a.mesh.morph_targets[0].rest_weight = 0.5f;  // the unit encoding's rest weight
  Result<std::string> text = usdaLayer(a);
  ASSERT_TRUE(text.ok()) << text.message();
  EXPECT_EQ(text->find("timeSamples"), std::string::npos);
  EXPECT_NE(text->find("float[] blendShapeWeights = [0.5]"), std::string::npos);
  EXPECT_NE(text->find("quatf[] rotations = [(1, 0, 0, 0), (1, 0, 0, 0), (1, 0, 0, 0)]"),
            std::string::npos);
  EXPECT_EQ(text->find("primvars:st"), std::string::npos);  // no UVs
}

TEST(UsdLayer, RefusesWhatUsdCannotHold) {
  Asset a = test::makeAsset({3, 6, 2, true, 1, 2});
  Asset named = a;
  named.skeleton.names[1] = "left hip";
  EXPECT_EQ(usdaLayer(named).message(),
            "USD writer: joint name \"left hip\" is not a USD identifier "
            "([A-Za-z_][A-Za-z0-9_]*)");
  Asset twice = a;
  twice.skeleton.names[2] = twice.skeleton.names[1];
  EXPECT_NE(usdaLayer(twice).message().find("is not unique"), std::string::npos);
  Asset two_clips = a;
  two_clips.animations.push_back(a.animations[0]);
  EXPECT_EQ(usdaLayer(two_clips).message(),
            "USD writer: the asset has 2 animations; a UsdSkel body binds one");
  Asset quantized = a;
  quantized.mesh.morph_targets[0].quantized = true;
  EXPECT_NE(usdaLayer(quantized).message().find("is quantized"), std::string::npos);
  Asset target = a;
  target.mesh.morph_targets[0].name = "pose/x";
  EXPECT_NE(usdaLayer(target).message().find("morph target name \"pose/x\""), std::string::npos);
  Asset off_grid = a;
  off_grid.animations[0].times[1] = 0.05;
  EXPECT_NE(usdaLayer(off_grid).message().find("frame 1 is not at time code 1"), std::string::npos);
}

TEST(UsdLayer, DotUsdIsTheTextLayer) {  // USD reads a .usd as text or binary by its content
  EXPECT_EQ(writerFormatForPath("DIR/body.USD"), writerFormatByName("usda"));
  EXPECT_EQ(writerFormatForPath("body.usdz"), writerFormatByName("usdz"));
}

TEST(UsdLayer, UsdzHoldsTheLayerAsItsFirstFile) {
  const Asset a = test::makeAsset({3, 6, 2, true, 1, 2});
  Result<std::string> zip = writerFormatByName("usdz")->writer->serialize(a, WriterOptions{});
  ASSERT_TRUE(zip.ok()) << zip.message();
  const auto* data = reinterpret_cast<const uint8_t*>(zip->data());
  Result<std::vector<ZipEntry>> entries = readZip(data, zip->size(), "t.usdz");
  ASSERT_TRUE(entries.ok()) << entries.message();
  ASSERT_EQ(entries->size(), 1u);
  EXPECT_EQ((*entries)[0].name, "body.usda");
  const std::string inside((*entries)[0].data.begin(), (*entries)[0].data.end());
  EXPECT_EQ(inside, *usdaLayer(a));
}

}  // namespace
}  // namespace smpl
