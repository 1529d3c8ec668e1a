// Compact glTF encodings: sparse morph targets, quantized morph targets
// (KHR_mesh_quantization, per-target scale folded into the weights) and Draco
// base meshes. Each file is read back with tinygltf (plus Draco) and compared
// with the asset's own numbers, not with earlier output.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <random>

#include "exporter/morph_scales.h"
#include "tests/unit/test_asset.h"
#include "tools/morph_error.h"
#include "writers/gltf/gltf_writer.h"

namespace smpl {
namespace {

// 40 vertices on a grid, 3 joints, 2 correctives (one with deltas spanning
// 1e-6..1e-2, one all below 1e-5) and one shape key without a corrective entry.
Asset compactAsset() {
  Asset a;
  a.name = "body";
  Eigen::MatrixXd rest_world(3, 3);
  rest_world << 0, 1, 0, 0.1, 0.9, 0, 0.1, 0.5, 0;
  a.skeleton = test::skeletonFromWorld({"pelvis", "left_hip", "left_knee"}, {-1, 0, 1}, rest_world);
  const int v = 40;
  SkinnedMesh& m = a.mesh;
  m.positions.resize(v, 3);
  m.normals = Eigen::MatrixXf::Zero(v, 3);
  m.normals.col(2).setOnes();
  m.joints = Eigen::MatrixXi::Zero(v, 1);
  m.weights = Eigen::MatrixXf::Ones(v, 1);
  for (int i = 0; i < v; ++i) m.positions.row(i) << float(i % 8) * 0.05f, float(i / 8) * 0.2f, 0.f;
  m.triangles.resize(2 * 4 * 7, 3);
  int f = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 7; ++c) {
      const int i = r * 8 + c;
      m.triangles.row(f++) << i, i + 1, i + 8;
      m.triangles.row(f++) << i + 1, i + 9, i + 8;
    }
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  const float magnitude[3] = {0.01f, 8e-6f, 0.05f};
  const char* names[3] = {"pose_left_hip_00", "pose_left_hip_01", "shape_0"};
  for (int t = 0; t < 3; ++t) {
    MorphTarget target;
    target.name = names[t];
    target.deltas.resize(v, 3);
    for (int i = 0; i < v; ++i)
      for (int c = 0; c < 3; ++c)  // every 4th vertex large, the rest tiny
        target.deltas(i, c) = u(rng) * magnitude[t] * (i % 4 == 0 ? 1.f : 1e-3f);
    m.morph_targets.push_back(target);
  }
  a.metadata.correctives = {{0, "pose_left_hip_00", 1.0, 0.0}, {1, "pose_left_hip_01", 0.5, 0.5}};
  a.mesh.morph_targets[1].rest_weight = 0.5f;
  return a;
}

std::string write(const Asset& a, const WriterOptions& o) {
  Result<std::string> bytes = gltfWriter().serialize(a, o);
  EXPECT_TRUE(bytes.ok()) << (bytes ? "" : bytes.message());
  return bytes ? *bytes : std::string();
}

TEST(GltfCompact, SparseKeepsExactlyTheDeltasAboveEpsilon) {
  const Asset a = compactAsset();
  WriterOptions o;
  o.morph_epsilon = 1e-4;
  Result<DecodedMorphs> d = decodeMorphs(write(a, o));
  ASSERT_TRUE(d.ok()) << d.message();
  ASSERT_EQ(d->deltas.size(), 3u);
  for (size_t t = 0; t < 3; ++t) {
    const Eigen::MatrixXf& exact = a.mesh.morph_targets[t].deltas;
    int kept = 0;
    for (int i = 0; i < exact.rows(); ++i) {
      const bool keep = exact.row(i).cast<double>().norm() > 1e-4;
      kept += keep;
      const bool listed = keep || (t == 1 && i == 0);  // nothing kept: vertex 0 stands in
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(d->deltas[t](i, c), listed ? exact(i, c) : 0.f)
            << "target " << t << " vertex " << i;
    }
    if (t == 1) {
      EXPECT_EQ(kept, 0);  // all tiny (see gltf_morphs.h)
    } else {
      EXPECT_GT(kept, 0);
    }
  }
  // Target 1 keeps vertex 0 exactly, so its error is the rest below epsilon.
  Result<double> err = morphError(*d, a);
  ASSERT_TRUE(err.ok()) << err.message();
  EXPECT_GT(*err, 0.0);
  // Per pose: sum over targets of |w_n| * (dropped |d| <= 1e-4); |w| <= 2 here.
  EXPECT_LE(*err, 2 * 2 * 1e-4 + 0.05 * 1e-4);
}

TEST(GltfCompact, QuantizedWithinHalfAStepOfThePerTargetScale) {
  const Asset a = compactAsset();
  Asset folded = a;  // what exportAsset does for --quantize-morphs
  foldMorphScales(&folded);
  EXPECT_TRUE(folded.mesh.morph_targets[0].quantized && folded.mesh.morph_targets[1].quantized);
  EXPECT_FALSE(folded.mesh.morph_targets[2].quantized);  // no corrective entry: stays FLOAT
  Result<DecodedMorphs> d = decodeMorphs(write(folded, WriterOptions()));
  ASSERT_TRUE(d.ok()) << d.message();
  const std::vector<double> s = morphWeightScales(a);
  ASSERT_EQ(d->correctives.size(), 2u);
  for (size_t t = 0; t < 3; ++t) {
    const Eigen::MatrixXf& exact = a.mesh.morph_targets[t].deltas;
    const double peak = exact.cwiseAbs().maxCoeff();
    const double step = t < 2 ? peak / 32767 : 0.0;  // shape_0 stays FLOAT
    EXPECT_EQ(s[t], t < 2 ? peak : 1.0);
    const Eigen::MatrixXd decoded = d->deltas[t].cast<double>() * s[t];
    EXPECT_LE((decoded - exact.cast<double>()).cwiseAbs().maxCoeff(), 0.5 * step + 1e-9 * peak);
  }
  // The weights carry s_n: metadata scale/offset and the rest weight.
  EXPECT_DOUBLE_EQ(d->correctives[0].scale, s[0]);
  EXPECT_DOUBLE_EQ(d->correctives[1].scale, 0.5 * s[1]);
  EXPECT_DOUBLE_EQ(d->correctives[1].offset, 0.5 * s[1]);
  EXPECT_NEAR(d->rest_weights[1], 0.5 * s[1], 1e-7 * s[1]);
  Result<double> err = morphError(*d, a);
  ASSERT_TRUE(err.ok()) << err.message();
  EXPECT_LE(*err, 4 * (s[0] + s[1]) / 32767);
}

// The writer computes no scale: it stores the targets the asset marks
// quantized as int16 and everything else as given.
TEST(GltfCompact, WriterQuantizesExactlyTheMarkedTargets) {
  Asset a = compactAsset();
  a.mesh.morph_targets[0].deltas /= a.mesh.morph_targets[0].deltas.cwiseAbs().maxCoeff();
  a.mesh.morph_targets[0].quantized = true;
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const std::string bytes = write(a, WriterOptions());
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&m, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(bytes.data()),
                                          unsigned(bytes.size())))
      << err;
  const auto& targets = m.meshes[0].primitives[0].targets;
  ASSERT_EQ(targets.size(), 3u);
  EXPECT_EQ(m.accessors[size_t(targets[0].at("POSITION"))].componentType,
            TINYGLTF_COMPONENT_TYPE_SHORT);
  EXPECT_EQ(m.accessors[size_t(targets[1].at("POSITION"))].componentType,
            TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(m.accessors[size_t(targets[2].at("POSITION"))].componentType,
            TINYGLTF_COMPONENT_TYPE_FLOAT);
  Result<DecodedMorphs> d = decodeMorphs(bytes);
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_DOUBLE_EQ(d->correctives[0].scale, 1.0);  // the metadata as the asset has it
  EXPECT_LE((d->deltas[0] - a.mesh.morph_targets[0].deltas).cwiseAbs().maxCoeff(),
            0.5f / 32767 + 1e-7f);
}

// --corrective-epsilon is metres also for quantized targets: the writer
// compares |d| * peak (the folded deltas are d / s_n), so the kept vertices are
// those of the unquantized export.
TEST(GltfCompact, EpsilonIsMetresForQuantizedTargets) {
  const Asset a = compactAsset();
  Asset folded = a;
  foldMorphScales(&folded);
  WriterOptions o;
  o.morph_epsilon = 1e-4;
  Result<DecodedMorphs> d = decodeMorphs(write(folded, o));
  ASSERT_TRUE(d.ok()) << d.message();
  const Eigen::MatrixXf& exact = a.mesh.morph_targets[0].deltas;  // quantized, peak ~1e-2
  int kept = 0;
  for (int i = 0; i < exact.rows(); ++i) {
    const bool keep = exact.row(i).cast<double>().norm() > 1e-4;
    kept += keep;
    EXPECT_EQ(d->deltas[0].row(i).isZero(), !keep) << "vertex " << i;
  }
  EXPECT_GT(kept, 0);
  EXPECT_LT(kept, exact.rows());
}

TEST(GltfCompact, FoldingTwiceIsTheIdentity) {
  Asset a = compactAsset();
  foldMorphScales(&a);
  const Asset once = a;
  foldMorphScales(&a);
  for (size_t t = 0; t < 3; ++t)
    EXPECT_EQ(a.mesh.morph_targets[t].deltas, once.mesh.morph_targets[t].deltas);
  EXPECT_EQ(a.metadata.correctives[1].scale, once.metadata.correctives[1].scale);
}

TEST(GltfCompact, DracoDecodesPositionsInVertexOrder) {
  const Asset a = compactAsset();
  WriterOptions o;
  o.draco = true;
  Result<DecodedMorphs> d = decodeMorphs(write(a, o));
  ASSERT_TRUE(d.ok()) << d.message();
  // 16-bit quantisation over the bounding cube (extent 0.8 m here): half a step.
  const double half_step = 0.8 / 65535 / 2;
  EXPECT_LE((d->positions - a.mesh.positions).cwiseAbs().maxCoeff(), half_step * 1.01);
  for (size_t t = 0; t < 3; ++t) EXPECT_EQ(d->deltas[t], a.mesh.morph_targets[t].deltas);
}

TEST(GltfCompact, SceneExtrasCarryTheMetadata) {
  const Asset a = compactAsset();
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const std::string bytes = write(a, WriterOptions());
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&m, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(bytes.data()),
                                          unsigned(bytes.size())))
      << err;
  ASSERT_EQ(m.scenes.size(), 1u);
  const tinygltf::Value& scene = m.scenes[0].extras.Get("smpl");
  const tinygltf::Value& asset = m.asset.extras.Get("smpl");
  ASSERT_TRUE(scene.IsObject());
  EXPECT_EQ(scene.Get("joint_names").ArrayLen(), 3u);
  EXPECT_TRUE(scene == asset);
}

}  // namespace
}  // namespace smpl
