// --scene in the glTF writer: bodies composed on one timeline
// (exporter/scene_timeline.h) and written as one file (gltf_scene.cpp), read
// back with tinygltf's loader. The camera is checked as directions: the
// glTF camera looks down its -Z with +Y up, so its node rotation must send
// (0, 0, -1) to the OpenCV camera's forward (R z) and (0, 1, 0) to its up
// (-R y), both turned by the world turn; computed here from the OpenCV
// definition, not from the writer's matrix.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exporter/metadata_json.h"
#include "exporter/scene_timeline.h"
#include "tests/unit/test_asset.h"
#include "writers/gltf/gltf_writer.h"

namespace smpl {
namespace {

using test::AssetSpec;
using test::makeAsset;

constexpr double kFps = 30.0;

// A body whose one clip covers source frames [first, first + frames).
SceneBodyInput body(const std::string& name, const std::string& track, int64_t first, int frames) {
  AssetSpec spec;
  spec.frames = frames;
  Asset a = makeAsset(spec);
  a.name = name;
  a.animations[0].source.first_frame = first;
  a.animations[0].source.end_frame = first + frames;
  return SceneBodyInput{a, track};
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// Three camera frames from source frame 2: varied rotations and centres.
SceneCamera camera() {
  SceneCamera c;
  c.first_frame = 2;
  c.rotation = {Eigen::Matrix3d::Identity(), rotation(0.7, {0, 1, 0}),
                rotation(2.5, {0.3, -1, 0.4})};
  c.position = {{1, 2, 3}, {-0.5, 1.5, 4}, {0.25, -1, 2}};
  c.yfov = 0.9;
  c.aspect = 16.0 / 9.0;
  return c;
}

tinygltf::Model load(const std::string& bytes) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(bytes.data()),
                                          unsigned(bytes.size())))
      << err;
  return model;
}

std::vector<double> floats(const tinygltf::Model& m, int index) {
  const tinygltf::Accessor& acc = m.accessors.at(size_t(index));
  EXPECT_EQ(acc.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  const tinygltf::BufferView& view = m.bufferViews.at(size_t(acc.bufferView));
  const unsigned char* p =
      m.buffers.at(size_t(view.buffer)).data.data() + view.byteOffset + acc.byteOffset;
  const size_t n = acc.count * size_t(tinygltf::GetNumComponentsInType(uint32_t(acc.type)));
  std::vector<double> out(n);
  for (size_t i = 0; i < n; ++i) {
    float f;
    std::memcpy(&f, p + 4 * i, 4);
    out[i] = f;
  }
  return out;
}

struct Channel {
  std::vector<double> times, values;
  std::string interpolation;
};

// The channel of the scene's one animation on `node`'s `path` (empty times: none).
Channel channel(const tinygltf::Model& m, int node, const std::string& path) {
  Channel c;
  EXPECT_EQ(m.animations.size(), 1u);
  for (const tinygltf::AnimationChannel& ch : m.animations.at(0).channels) {
    if (ch.target_node != node || ch.target_path != path) continue;
    const tinygltf::AnimationSampler& s = m.animations[0].samplers.at(size_t(ch.sampler));
    c.times = floats(m, s.input);
    c.values = floats(m, s.output);
    c.interpolation = s.interpolation;
  }
  return c;
}

int nodeNamed(const tinygltf::Model& m, const std::string& name) {
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].name == name) return int(i);
  return -1;
}

std::string written(const SceneAsset& scene) {
  Result<Writer::Files> files = gltfWriter().serializeSceneFiles(scene, WriterOptions());
  EXPECT_TRUE(files.ok()) << (files.ok() ? "" : files.message());
  if (!files.ok()) return {};
  return files->bytes + withSplices(files->tail, files->splices);
}

Result<SceneAsset> twoBodies(const SceneCamera& cam, const Eigen::Matrix3d& turn) {
  std::vector<SceneBodyInput> bodies;
  bodies.push_back(body("body_0", "0", 3, 5));  // frames 3..7
  bodies.push_back(body("body_1", "1", 0, 5));  // frames 0..4
  return composeScene("walk", std::move(bodies), kFps, cam, turn, "walk.pkl");
}

TEST(GltfScene, CameraNodeLooksWhereTheOpenCvCameraLooks) {
  for (const Eigen::Matrix3d& turn :
       {Eigen::Matrix3d(Eigen::Matrix3d::Identity()),
        Eigen::Matrix3d(Eigen::Vector3d(1, -1, -1).asDiagonal()),  // --up -y
        rotation(-M_PI / 2, {1, 0, 0})}) {                         // --up z
    const SceneCamera cam = camera();
    Result<SceneAsset> scene = twoBodies(cam, turn);
    ASSERT_TRUE(scene.ok()) << scene.message();
    const tinygltf::Model m = load(written(*scene));
    const int node = nodeNamed(m, "camera");
    ASSERT_GE(node, 0);
    ASSERT_EQ(m.nodes[size_t(node)].camera, 0);
    ASSERT_EQ(m.cameras.size(), 1u);
    EXPECT_EQ(m.cameras[0].type, "perspective");
    EXPECT_NEAR(m.cameras[0].perspective.yfov, 0.9, 1e-12);
    EXPECT_NEAR(m.cameras[0].perspective.aspectRatio, 16.0 / 9.0, 1e-12);
    const Channel t = channel(m, node, "translation"), r = channel(m, node, "rotation");
    ASSERT_EQ(t.times.size(), 3u);
    ASSERT_EQ(r.values.size(), 12u);
    for (size_t f = 0; f < 3; ++f) {
      // Source frame 2 + f on a timeline that starts at frame 0 (body_1).
      EXPECT_NEAR(t.times[f], (2.0 + double(f)) / kFps, 1e-6);
      const Eigen::Vector3d want_position = turn * cam.position[f];
      const Eigen::Quaterniond q(r.values[4 * f + 3], r.values[4 * f], r.values[4 * f + 1],
                                 r.values[4 * f + 2]);
      const Eigen::Vector3d forward = q * Eigen::Vector3d(0, 0, -1);
      const Eigen::Vector3d up = q * Eigen::Vector3d(0, 1, 0);
      const Eigen::Vector3d cv_forward = turn * cam.rotation[f].col(2);
      const Eigen::Vector3d cv_up = -(turn * cam.rotation[f].col(1));
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(t.values[3 * f + size_t(i)], want_position[i], 1e-6) << "frame " << f;
        EXPECT_NEAR(forward[i], cv_forward[i], 1e-6) << "frame " << f;
        EXPECT_NEAR(up[i], cv_up[i], 1e-6) << "frame " << f;
      }
    }
  }
}

TEST(GltfScene, BodiesKeepTheirOwnNodesSkinsAndMeshesOnOneTimeline) {
  Result<SceneAsset> scene = twoBodies(SceneCamera(), Eigen::Matrix3d::Identity());
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->first_frame, 0);
  EXPECT_EQ(scene->end_frame, 8);
  const tinygltf::Model m = load(written(*scene));
  EXPECT_TRUE(m.cameras.empty());
  ASSERT_EQ(m.skins.size(), 2u);
  ASSERT_EQ(m.meshes.size(), 2u);
  const int k = int(scene->bodies[0].asset.skeleton.names.size());
  for (int b = 0; b < 2; ++b) {
    // Body b: its node, its K joints, its mesh node.
    const std::string name = "body_" + std::to_string(b);
    const int body_node = nodeNamed(m, name), mesh_node = nodeNamed(m, name + "_mesh");
    ASSERT_EQ(body_node, b * (k + 2)) << name;
    ASSERT_EQ(mesh_node, b * (k + 2) + k + 1) << name;
    EXPECT_EQ(m.nodes[size_t(mesh_node)].skin, b);
    EXPECT_EQ(m.nodes[size_t(mesh_node)].mesh, b);
    EXPECT_EQ(m.skins[size_t(b)].name, name);
    EXPECT_EQ(m.meshes[size_t(b)].name, name + "_mesh");
    const int root = m.skins[size_t(b)].joints.at(0);
    EXPECT_EQ(root, body_node + 1);
    EXPECT_EQ(m.nodes[size_t(body_node)].children, std::vector<int>{root});
    EXPECT_EQ(m.nodes[size_t(root)].name, "pelvis");
    // The clip's keys at the body's start: body_0 starts at frame 3, body_1 at 0.
    const Channel rot = channel(m, root, "rotation");
    ASSERT_EQ(rot.times.size(), 5u);
    EXPECT_NEAR(rot.times[0], b == 0 ? 3.0 / kFps : 0.0, 1e-7);
    EXPECT_NEAR(rot.times[4], (b == 0 ? 7.0 : 4.0) / kFps, 1e-6);
    // Hidden outside its frames: STEP scale keys on the body node, half a
    // frame before each change.
    EXPECT_TRUE(channel(m, root, "scale").times.empty());
    const Channel scale = channel(m, body_node, "scale");
    EXPECT_EQ(scale.interpolation, "STEP");
    const std::vector<double> want_times =
        b == 0 ? std::vector<double>{0.0, 2.5 / kFps} : std::vector<double>{0.0, 4.5 / kFps};
    const std::vector<double> want_scale =
        b == 0 ? std::vector<double>{0, 0, 0, 1, 1, 1} : std::vector<double>{1, 1, 1, 0, 0, 0};
    ASSERT_EQ(scale.times.size(), want_times.size()) << name;
    for (size_t i = 0; i < want_times.size(); ++i)
      EXPECT_NEAR(scale.times[i], want_times[i], 1e-7) << name;
    EXPECT_EQ(scale.values, want_scale) << name;
  }
  const std::vector<int> roots = m.scenes.at(0).nodes;
  EXPECT_EQ(roots, (std::vector<int>{0, k + 1, k + 2, 2 * k + 3}));
}

TEST(GltfScene, MetadataListsTheBodiesOnTheTimeline) {
  Result<SceneAsset> scene = twoBodies(camera(), Eigen::Matrix3d::Identity());
  ASSERT_TRUE(scene.ok()) << scene.message();
  const nlohmann::json o = nlohmann::json::parse(sceneMetadataJson(*scene));
  EXPECT_EQ(o["scene"]["first_frame"], 0);
  EXPECT_EQ(o["scene"]["end_frame"], 8);
  ASSERT_EQ(o["scene"]["bodies"].size(), 2u);
  EXPECT_EQ(o["scene"]["bodies"][0]["name"], "body_0");
  EXPECT_EQ(o["scene"]["bodies"][0]["track"], "0");
  EXPECT_EQ(o["scene"]["bodies"][0]["first_frame"], 3);
  EXPECT_EQ(o["scene"]["bodies"][1]["end_frame"], 5);
  EXPECT_EQ(o["scene"]["camera"]["frames"], 3);
  ASSERT_EQ(o["bodies"].size(), 2u);
  EXPECT_EQ(o["bodies"][0]["model_kind"], "smpl");
}

TEST(GltfScene, BodyShownThroughoutHasNoScaleChannel) {
  std::vector<SceneBodyInput> bodies;
  bodies.push_back(body("body", "", 4, 6));
  Result<SceneAsset> scene =
      composeScene("one", std::move(bodies), kFps, SceneCamera(), Eigen::Matrix3d::Identity(), "f");
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_TRUE(scene->bodies[0].visibility.empty());
  EXPECT_EQ(scene->bodies[0].start, 0.0);
  const tinygltf::Model m = load(written(*scene));
  EXPECT_TRUE(m.animations.at(0).channels.size() > 0);
  for (const tinygltf::AnimationChannel& ch : m.animations[0].channels)
    EXPECT_NE(ch.target_path, "scale");
}

TEST(GltfScene, BodyIsHiddenOnFramesWithoutADetection) {
  // Frames 0..5 of a scene with a second body on 0..7; frames 2 and 3 are held, not detected.
  std::vector<SceneBodyInput> bodies;
  bodies.push_back(body("body_0", "0", 0, 6));
  bodies.back().detected = {true, true, false, false, true, true};
  bodies.push_back(body("body_1", "1", 0, 8));
  Result<SceneAsset> scene =
      composeScene("gap", std::move(bodies), kFps, SceneCamera(), Eigen::Matrix3d::Identity(), "f");
  ASSERT_TRUE(scene.ok()) << scene.message();
  const SceneBody& b = scene->bodies[0];
  EXPECT_EQ(b.visibility, (std::vector<float>{1, 0, 1, 0}));
  ASSERT_EQ(b.visibility_times.size(), 4u);
  EXPECT_EQ(b.visibility_times[0], 0.0);
  EXPECT_DOUBLE_EQ(b.visibility_times[1], 1.5 / kFps);
  EXPECT_DOUBLE_EQ(b.visibility_times[2], 3.5 / kFps);
  EXPECT_DOUBLE_EQ(b.visibility_times[3], 5.5 / kFps);
  EXPECT_TRUE(scene->bodies[1].visibility.empty());
}

TEST(GltfScene, CameraWithoutFieldOfViewGetsTheDefaultAndANote) {
  SceneCamera cam = camera();
  cam.yfov = 0.0;
  Result<SceneAsset> scene = twoBodies(cam, Eigen::Matrix3d::Identity());
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_NEAR(scene->camera.yfov, M_PI / 3, 1e-12);
  ASSERT_EQ(scene->notes.size(), 1u);
  EXPECT_NE(scene->notes[0].find("no field of view"), std::string::npos);
}

TEST(GltfScene, BadCamerasAreRefused) {
  SceneCamera short_positions = camera();
  short_positions.position.pop_back();
  Result<SceneAsset> a = twoBodies(short_positions, Eigen::Matrix3d::Identity());
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.message(), "walk.pkl: the camera has 3 rotations for 2 positions");
  SceneCamera scaled = camera();
  scaled.rotation[1] *= 2.0;
  Result<SceneAsset> b = twoBodies(scaled, Eigen::Matrix3d::Identity());
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.message(), "walk.pkl: camera frame 1 is not a finite rotation and position");
  SceneCamera nan = camera();
  nan.position[2].x() = std::nan("");
  EXPECT_FALSE(twoBodies(nan, Eigen::Matrix3d::Identity()).ok());
}

}  // namespace
}  // namespace smpl
