// validateAssetStructure through both writers: each rule (the strictest of the
// old glTF and FBX checks) rejects a broken asset in validateAsset, in the
// glTF writer and in the FBX writer, with the same message; the unbroken
// asset passes all three.
#include "exporter/validate_structure.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <functional>

#include "exporter/validate_asset.h"
#include "tests/unit/test_asset.h"
#include "writers/fbx/fbx_writer.h"
#include "writers/gltf/gltf_writer.h"

namespace smpl {
namespace {

struct Rule {
  const char* name;
  std::function<void(Asset&)> brk;
  const char* fragment;  // in the error message
};

// 10 joints, 12 vertices, 4 influences, 2 morph targets, a 4-frame clip.
Asset good() {
  test::AssetSpec spec;
  spec.frames = 4;
  return test::makeAsset(spec);
}

const std::vector<Rule>& rules() {
  static const std::vector<Rule> r = {
      {"no joints", [](Asset& a) { a.skeleton.names.clear(); }, "skeleton has no joints"},
      {"parents count", [](Asset& a) { a.skeleton.parents.pop_back(); }, "names but 9 parents"},
      {"root not first", [](Asset& a) { a.skeleton.parents[0] = 1; },
       "joint 0 ('pelvis') has parent 1"},
      {"second root", [](Asset& a) { a.skeleton.parents[3] = -1; },
       "joint 3 ('joint_3') has parent -1"},
      {"forward parent", [](Asset& a) { a.skeleton.parents[3] = 5; },
       "has parent 5; expected 0..2"},
      {"rest_local shape", [](Asset& a) { a.skeleton.rest_local.conservativeResize(9, 3); },
       "skeleton rest_local has shape (9,3)"},
      {"no vertices", [](Asset& a) { a.mesh.positions.resize(0, 3); }, "mesh has no vertices"},
      {"missing normals", [](Asset& a) { a.mesh.normals.resize(0, 3); },
       "mesh normals has shape (0,3)"},
      {"uv rows", [](Asset& a) { a.mesh.uvs.conservativeResize(5, 2); },
       "mesh uvs has shape (5,2)"},
      {"no triangles", [](Asset& a) { a.mesh.triangles.resize(0, 3); },
       "mesh triangles have shape (0,3)"},
      {"triangle index", [](Asset& a) { a.mesh.triangles(4, 2) = 12; },
       "triangle index out of range"},
      {"no influences",
       [](Asset& a) {
         a.mesh.joints.resize(12, 0);
         a.mesh.weights.resize(12, 0);
       },
       "no skin influences"},
      {"weights shape", [](Asset& a) { a.mesh.weights.conservativeResize(12, 3); },
       "mesh skin weights has shape"},
      {"joint index", [](Asset& a) { a.mesh.joints(2, 1) = 10; },
       "vertex 2 uses joint 10; expected 0..9"},
      {"negative weight", [](Asset& a) { a.mesh.weights(5, 0) = -0.25f; },
       "vertex 5 has skin weight"},
      {"zero weights", [](Asset& a) { a.mesh.weights.row(4).setZero(); },
       "vertex 4 has no positive skin weight"},
      {"morph target shape", [](Asset& a) { a.mesh.morph_targets[1].deltas.resize(3, 3); },
       "morph target 'pose_joint_1_01' has shape (3,3)"},
      {"quantized above 1",
       [](Asset& a) {
         a.mesh.morph_targets[0].quantized = true;
         a.mesh.morph_targets[0].deltas(3, 1) = 1.5f;
       },
       "morph target 'pose_joint_1_00' is quantized"},
      {"no frames",
       [](Asset& a) {
         AnimationClip& c = a.animations[0];
         c.times.clear();
         for (auto& track : c.rotations) track.clear();
         c.root_translation.clear();
         c.morph_weights.resize(0, 2);
       },
       "animation 'walk': no frames"},
      {"fps", [](Asset& a) { a.animations[0].fps = 0; }, "animation 'walk': fps"},
      {"negative time", [](Asset& a) { a.animations[0].times[0] = -0.5; }, "key time of frame 0"},
      {"equal times", [](Asset& a) { a.animations[0].times[2] = a.animations[0].times[1]; },
       "key time of frame 2"},
      {"decreasing times", [](Asset& a) { a.animations[0].times[3] = 0.01; },
       "strictly increasing"},
      {"times equal in float",
       [](Asset& a) { a.animations[0].times[2] = a.animations[0].times[1] + 1e-12; },
       "strictly increasing"},
      {"rotation tracks", [](Asset& a) { a.animations[0].rotations.pop_back(); },
       "9 rotation tracks; expected 10"},
      {"rotation keys", [](Asset& a) { a.animations[0].rotations[6].pop_back(); },
       "joint 6 has 3 rotation keys; expected 4"},
      {"zero rotation",
       [](Asset& a) { a.animations[0].rotations[2][1] = Eigen::Quaternionf(0, 0, 0, 0); },
       "joint 2 has a zero or non-finite rotation"},
      {"root translations", [](Asset& a) { a.animations[0].root_translation.pop_back(); },
       "3 root translations; expected 4"},
      {"morph weights shape",
       [](Asset& a) { a.animations[0].morph_weights.conservativeResize(4, 1); },
       "morph weights has shape (4,1); expected (4,2)"},
  };
  return r;
}

TEST(ValidateStructure, TheTestAssetPassesEveryWriter) {
  const Asset a = good();
  EXPECT_TRUE(validateAsset(a).ok()) << validateAsset(a).message();
  Result<std::string> glb = gltfWriter().serialize(a, WriterOptions());
  EXPECT_TRUE(glb.ok()) << glb.message();
  Result<std::string> fbx = fbxWriter().serialize(a, WriterOptions());
  EXPECT_TRUE(fbx.ok()) << fbx.message();
}

TEST(ValidateStructure, EachRuleRejectsABrokenAssetInBothFormats) {
  for (const Rule& rule : rules()) {
    SCOPED_TRACE(rule.name);
    Asset a = good();
    rule.brk(a);
    const Status st = validateAsset(a);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find(rule.fragment), std::string::npos) << st.message();
    Result<std::string> glb = gltfWriter().serialize(a, WriterOptions());
    ASSERT_FALSE(glb.ok()) << "glTF accepted it";
    EXPECT_EQ(glb.message(), st.message());
    Result<std::string> fbx = fbxWriter().serialize(a, WriterOptions());
    ASSERT_FALSE(fbx.ok()) << "FBX accepted it";
    EXPECT_EQ(fbx.message(), st.message());
  }
}

// A clip baked for an asset without morph targets has T x 0 weights: no
// weight channel, accepted by both formats (the glTF writer refused it before).
TEST(ValidateStructure, ClipWithoutMorphTargetsIsAccepted) {
  test::AssetSpec spec;
  spec.frames = 3;
  spec.morph_targets = 0;
  Asset a = test::makeAsset(spec);
  a.metadata.correctives.clear();
  ASSERT_EQ(a.animations[0].morph_weights.rows(), 3);
  ASSERT_EQ(a.animations[0].morph_weights.cols(), 0);
  EXPECT_TRUE(validateAsset(a).ok()) << validateAsset(a).message();
  Result<std::string> glb = gltfWriter().serialize(a, WriterOptions());
  ASSERT_TRUE(glb.ok()) << glb.message();
  EXPECT_TRUE(fbxWriter().serialize(a, WriterOptions()).ok());
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(
      &m, &err, &warn, reinterpret_cast<const unsigned char*>(glb->data()), unsigned(glb->size())))
      << err;
  ASSERT_EQ(m.animations.size(), 1u);
  EXPECT_EQ(m.animations[0].channels.size(), 11u);  // 10 rotations + the root translation
  for (const tinygltf::AnimationChannel& c : m.animations[0].channels)
    EXPECT_NE(c.target_path, "weights");
}

}  // namespace
}  // namespace smpl
