// EXT_meshopt_compression (--meshopt) and quantised animation keys
// (--quantize-animation). The meshopt file is decoded with meshoptimizer's own
// decoder and compared with the same asset written without --meshopt (every
// view decodes to exactly the bytes it would otherwise hold); quantised keys
// are compared with the asset's rotations and weights, not with earlier output.
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>

#include "tests/unit/test_asset.h"
#include "writers/gltf/gltf_writer.h"

namespace smpl {
namespace {

struct Glb {
  nlohmann::json doc;
  std::string bin;
};

uint32_t u32(const std::string& s, size_t at) {
  uint32_t v;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

Glb parseGlb(const std::string& glb) {
  Glb out;
  const uint32_t json_length = u32(glb, 12);
  out.doc = nlohmann::json::parse(glb.substr(20, json_length));
  const size_t bin_at = 20 + json_length;
  if (bin_at + 8 <= glb.size()) out.bin = glb.substr(bin_at + 8, u32(glb, bin_at));
  return out;
}

Asset animatedAsset(float weight_lo) {
  test::AssetSpec spec;
  spec.joints = 6;
  spec.vertices = 300;
  spec.morph_targets = 3;
  spec.frames = 21;  // 21 x 3 weights: an odd count of 16-bit keys
  Asset a = test::makeAsset(spec);
  std::mt19937 rng(5);
  a.animations[0].morph_weights = test::randomMatrix(rng, 21, 3, weight_lo, 1.f);
  return a;
}

Glb write(const Asset& a, bool meshopt, bool quantize) {
  WriterOptions o;
  o.meshopt = meshopt;
  o.quantize_animation = quantize;
  Result<std::string> bytes = gltfWriter().serialize(a, o);
  EXPECT_TRUE(bytes.ok()) << (bytes ? "" : bytes.message());
  return bytes ? parseGlb(*bytes) : Glb();
}

// The bytes the view holds once decoded (meshopt views) or as stored.
std::string viewBytes(const Glb& g, size_t v) {
  const nlohmann::json& view = g.doc["bufferViews"][v];
  const size_t length = view["byteLength"];
  if (!view.contains("extensions")) return g.bin.substr(view.value("byteOffset", 0), length);
  const nlohmann::json& e = view["extensions"]["EXT_meshopt_compression"];
  const size_t count = e["count"], stride = e["byteStride"];
  EXPECT_EQ(count * stride, length) << "view " << v;
  const auto* src = reinterpret_cast<const unsigned char*>(g.bin.data()) + size_t(e["byteOffset"]);
  std::string out(length, '\0');
  const int rc = e["mode"] == "INDICES"
                     ? meshopt_decodeIndexSequence(&out[0], count, stride, src, e["byteLength"])
                     : meshopt_decodeVertexBuffer(&out[0], count, stride, src, e["byteLength"]);
  EXPECT_EQ(rc, 0) << "view " << v;
  if (e.value("filter", "NONE") == "QUATERNION") meshopt_decodeFilterQuat(&out[0], count, stride);
  return out;
}

TEST(GltfMeshopt, EveryViewDecodesToTheBytesOfTheUncompressedFile) {
  const Asset a = animatedAsset(0.f);
  const Glb plain = write(a, false, false), packed = write(a, true, false);
  ASSERT_EQ(plain.doc["bufferViews"].size(), packed.doc["bufferViews"].size());
  int compressed = 0;
  for (size_t v = 0; v < plain.doc["bufferViews"].size(); ++v) {
    compressed += packed.doc["bufferViews"][v].contains("extensions");
    EXPECT_EQ(viewBytes(packed, v), viewBytes(plain, v)) << "view " << v;
  }
  // Positions, normals, UVs, joints, weights, indices, 3 targets, IBM, times, 6 rotations,
  // the root translation and the weights: every view of this asset.
  EXPECT_EQ(compressed, int(plain.doc["bufferViews"].size()));
  EXPECT_EQ(packed.doc["extensionsRequired"], nlohmann::json({"EXT_meshopt_compression"}));
  ASSERT_EQ(packed.doc["buffers"].size(), 2u);
  EXPECT_EQ(packed.doc["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"], true);
  EXPECT_FALSE(packed.doc["buffers"][1].contains("uri"));
  EXPECT_LT(packed.bin.size(), plain.bin.size());
  EXPECT_EQ(packed.doc["buffers"][0]["byteLength"], packed.bin.size());
}

// Decoded normalised keys of an accessor: c / 32767 (SHORT) or c / 65535 (UNSIGNED_SHORT).
std::vector<double> normalisedKeys(const Glb& g, const nlohmann::json& accessor) {
  EXPECT_TRUE(accessor.value("normalized", false));
  const std::string bytes = viewBytes(g, accessor["bufferView"]);
  const int type = accessor["componentType"];
  const size_t n = size_t(accessor["count"]) * (accessor["type"] == "VEC4" ? 4 : 1);
  std::vector<double> out(n);
  for (size_t i = 0; i < n; ++i) {
    if (type == TINYGLTF_COMPONENT_TYPE_SHORT) {
      int16_t c;
      std::memcpy(&c, bytes.data() + 2 * i, 2);
      out[i] = std::max(c / 32767.0, -1.0);
    } else {
      EXPECT_EQ(type, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
      uint16_t c;
      std::memcpy(&c, bytes.data() + 2 * i, 2);
      out[i] = c / 65535.0;
    }
  }
  return out;
}

// Max |decoded - q| over the rotation keys of every joint, up to the sign of q.
double rotationError(const Glb& g, const AnimationClip& clip) {
  const nlohmann::json& anim = g.doc["animations"][0];
  double worst = 0;
  for (const nlohmann::json& ch : anim["channels"]) {
    if (ch["target"]["path"] != "rotation") continue;
    const nlohmann::json& acc =
        g.doc["accessors"][size_t(anim["samplers"][size_t(ch["sampler"])]["output"])];
    EXPECT_EQ(acc["componentType"], TINYGLTF_COMPONENT_TYPE_SHORT);
    const std::vector<double> keys = normalisedKeys(g, acc);
    const auto& track = clip.rotations[size_t(ch["target"]["node"])];
    for (size_t f = 0; f < track.size(); ++f) {
      const Eigen::Vector4d q = track[f].cast<double>().normalized().coeffs();  // x, y, z, w
      const Eigen::Vector4d d(keys[4 * f], keys[4 * f + 1], keys[4 * f + 2], keys[4 * f + 3]);
      worst =
          std::max(worst, std::min((d - q).cwiseAbs().maxCoeff(), (d + q).cwiseAbs().maxCoeff()));
    }
  }
  return worst;
}

double weightError(const Glb& g, const AnimationClip& clip, int expected_type) {
  const nlohmann::json& anim = g.doc["animations"][0];
  for (const nlohmann::json& ch : anim["channels"]) {
    if (ch["target"]["path"] != "weights") continue;
    const nlohmann::json& acc =
        g.doc["accessors"][size_t(anim["samplers"][size_t(ch["sampler"])]["output"])];
    EXPECT_EQ(acc["componentType"], expected_type);
    const std::vector<double> keys = normalisedKeys(g, acc);
    double worst = 0;
    for (Eigen::Index f = 0; f < clip.morph_weights.rows(); ++f)
      for (Eigen::Index t = 0; t < clip.morph_weights.cols(); ++t)
        worst = std::max(worst, std::abs(keys[size_t(f * clip.morph_weights.cols() + t)] -
                                         double(clip.morph_weights(f, t))));
    return worst;
  }
  ADD_FAILURE() << "no weights channel";
  return 1;
}

TEST(GltfQuantizedAnimation, KeysWithinHalfAStep) {
  const Asset unit = animatedAsset(0.f);
  const Glb g = write(unit, false, true);
  EXPECT_LE(rotationError(g, unit.animations[0]), 0.5 / 32767 + 1e-7);
  EXPECT_LE(weightError(g, unit.animations[0], TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT),
            0.5 / 65535 + 1e-7);
  const Asset signed_weights = animatedAsset(-1.f);
  EXPECT_LE(weightError(write(signed_weights, false, true), signed_weights.animations[0],
                        TINYGLTF_COMPONENT_TYPE_SHORT),
            0.5 / 32767 + 1e-7);
  EXPECT_TRUE(g.doc.value("extensionsUsed", nlohmann::json::array()).empty()) << "core glTF only";
}

TEST(GltfQuantizedAnimation, WeightsBeyondOneStayFloat) {
  const Asset a = animatedAsset(-2.f);  // signed diagonal correctives reach -2
  const Glb g = write(a, false, true);
  const nlohmann::json& anim = g.doc["animations"][0];
  int channels = 0;
  for (const nlohmann::json& ch : anim["channels"]) {
    if (ch["target"]["path"] != "weights") continue;
    ++channels;
    EXPECT_EQ(g.doc["accessors"][size_t(anim["samplers"][size_t(ch["sampler"])]["output"])]
                   ["componentType"],
              TINYGLTF_COMPONENT_TYPE_FLOAT);
  }
  EXPECT_EQ(channels, 1);
}

TEST(GltfMeshopt, QuaternionFilterDecodesToTheRotationKeys) {
  const Asset a = animatedAsset(0.f);
  const Glb g = write(a, true, true);
  int filtered = 0;
  for (const nlohmann::json& view : g.doc["bufferViews"])
    filtered += view.contains("extensions") &&
                view["extensions"]["EXT_meshopt_compression"].value("filter", "") == "QUATERNION";
  EXPECT_EQ(filtered, 6);  // one rotation track per joint
  // 16-bit quaternion filter: three components in 16 bits over [-1/sqrt2, 1/sqrt2], the
  // fourth reconstructed, then stored as int16.
  EXPECT_LE(rotationError(g, a.animations[0]), 1e-4);
  EXPECT_LE(weightError(g, a.animations[0], TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT),
            0.5 / 65535 + 1e-7);
}

}  // namespace
}  // namespace smpl
