// --scene in the FBX writer (fbx_scene_bodies.cpp, fbx_camera.cpp): a
// two-body scene with a camera, composed as the request composes it
// (exporter/scene_timeline.h), written and read back by Assimp (Debian
// 5.2.5) as an independent reader: one mesh and skeleton per body under
// unique names, one animation, the camera. The camera is checked as
// directions computed here from the OpenCV definition: Assimp keeps the FBX
// camera's own axes (looking down its local +X, +Y up, aiCamera mLookAt and
// mUp), so the node's rotation must send +X to the OpenCV forward (R z) and
// +Y to its up (-R y). Also: the same scene gives the same bytes.
#ifdef SMPL_WITH_ASSIMP

#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "exporter/scene_timeline.h"
#include "tests/unit/test_asset.h"
#include "writers/fbx/fbx_writer.h"

namespace smpl {
namespace {

constexpr double kFps = 30.0;

SceneBodyInput body(const std::string& name, const std::string& track, int64_t first, int frames) {
  test::AssetSpec spec;
  spec.frames = frames;
  Asset a = test::makeAsset(spec);
  a.name = name;
  a.animations[0].source.first_frame = first;
  a.animations[0].source.end_frame = first + frames;
  return SceneBodyInput{a, track};
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

SceneCamera camera() {
  SceneCamera c;
  c.first_frame = 0;
  c.rotation = {rotation(2.5, {0.3, -1, 0.4}), rotation(0.7, {0, 1, 0})};
  c.position = {{1, 2, 3}, {-0.5, 1.5, 4}};
  c.yfov = 0.9;
  c.aspect = 16.0 / 9.0;
  return c;
}

SceneAsset twoBodies() {
  std::vector<SceneBodyInput> bodies;
  bodies.push_back(body("body_0", "0", 3, 5));  // frames 3..7
  bodies.push_back(body("body_1", "1", 0, 5));  // frames 0..4
  Result<SceneAsset> scene = composeScene("walk", std::move(bodies), kFps, camera(),
                                          Eigen::Matrix3d::Identity(), "walk.pkl");
  EXPECT_TRUE(scene.ok()) << scene.message();
  return scene.ok() ? std::move(*scene) : SceneAsset();
}

std::string written(const SceneAsset& scene) {
  Result<Writer::Files> files = fbxWriter().serializeSceneFiles(scene, WriterOptions());
  EXPECT_TRUE(files.ok()) << (files.ok() ? "" : files.message());
  return files.ok() ? files->bytes : std::string();
}

const aiNode* findNode(const aiNode* n, const std::string& name) {
  if (name == n->mName.C_Str()) return n;
  for (unsigned i = 0; i < n->mNumChildren; ++i)
    if (const aiNode* hit = findNode(n->mChildren[i], name)) return hit;
  return nullptr;
}

void collectNames(const aiNode* n, std::vector<std::string>* out) {
  out->push_back(n->mName.C_Str());
  for (unsigned i = 0; i < n->mNumChildren; ++i) collectNames(n->mChildren[i], out);
}

aiMatrix4x4 globalTransform(const aiNode* n) {
  aiMatrix4x4 m = n->mTransformation;
  for (const aiNode* p = n->mParent; p; p = p->mParent) m = p->mTransformation * m;
  return m;
}

Eigen::Vector3d apply(const aiMatrix4x4& m, const aiVector3D& v, bool point) {
  const double w = point ? 1.0 : 0.0;
  return {m.a1 * v.x + m.a2 * v.y + m.a3 * v.z + m.a4 * w,
          m.b1 * v.x + m.b2 * v.y + m.b3 * v.z + m.b4 * w,
          m.c1 * v.x + m.c2 * v.y + m.c3 * v.z + m.c4 * w};
}

TEST(FbxScene, AssimpReadsEveryBodyAndTheCamera) {
  const SceneAsset scene = twoBodies();
  const std::string bytes = written(scene);
  Assimp::Importer importer;
  const aiScene* s = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, "fbx");
  ASSERT_NE(s, nullptr) << importer.GetErrorString();
  ASSERT_EQ(s->mNumMeshes, 2u);
  std::set<std::string> meshes;
  for (unsigned i = 0; i < s->mNumMeshes; ++i) {
    meshes.insert(s->mMeshes[i]->mName.C_Str());
    EXPECT_EQ(s->mMeshes[i]->mNumBones, scene.bodies[0].asset.skeleton.names.size());
  }
  EXPECT_EQ(meshes, (std::set<std::string>{"body_0_mesh", "body_1_mesh"}));
  for (const SceneBody& b : scene.bodies) {
    const aiNode* node = findNode(s->mRootNode, b.asset.name);
    ASSERT_NE(node, nullptr) << b.asset.name;
    // The body node holds its own skeleton, in its namespace.
    EXPECT_NE(findNode(node, b.asset.name + ":" + b.asset.skeleton.names[0]), nullptr);
  }
  std::vector<std::string> names;
  collectNames(s->mRootNode, &names);
  std::set<std::string> unique(names.begin(), names.end());
  EXPECT_EQ(unique.size(), names.size()) << "a node name repeats";
  EXPECT_EQ(s->mNumAnimations, 1u);

  ASSERT_EQ(s->mNumCameras, 1u);
  const aiCamera* cam = s->mCameras[0];
  const SceneCamera want = camera();
  const double xfov = 2 * std::atan(want.aspect * std::tan(want.yfov / 2));
  EXPECT_NEAR(cam->mHorizontalFOV, xfov, 1e-5);  // Assimp reads FieldOfView as horizontal
  const aiNode* node = findNode(s->mRootNode, cam->mName.C_Str());
  ASSERT_NE(node, nullptr);
  // The node's rest transform is the first camera key (frame 0).
  const aiMatrix4x4 m = globalTransform(node);
  const Eigen::Vector3d forward = apply(m, cam->mLookAt, false).normalized();
  const Eigen::Vector3d up = apply(m, cam->mUp, false).normalized();
  const Eigen::Vector3d at = apply(m, cam->mPosition, true);
  EXPECT_LT((forward - want.rotation[0].col(2)).norm(), 1e-5) << forward.transpose();
  EXPECT_LT((up + want.rotation[0].col(1)).norm(), 1e-5) << up.transpose();
  EXPECT_LT((at - want.position[0]).norm(), 1e-5) << at.transpose();
}

TEST(FbxScene, SameSceneSameBytes) {
  const std::string a = written(twoBodies());
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, written(twoBodies()));
}

TEST(FbxScene, RefusesAnEmptySceneAndNamesABadBody) {
  EXPECT_FALSE(fbxWriter().serializeSceneFiles(SceneAsset(), WriterOptions()).ok());
  SceneAsset scene = twoBodies();
  scene.bodies[1].asset.skeleton.parents.pop_back();
  Result<Writer::Files> files = fbxWriter().serializeSceneFiles(scene, WriterOptions());
  ASSERT_FALSE(files.ok());
  EXPECT_NE(files.message().find("body 'body_1'"), std::string::npos) << files.message();
}

}  // namespace
}  // namespace smpl

#endif  // SMPL_WITH_ASSIMP
