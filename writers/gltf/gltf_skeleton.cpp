// glTF writer stage: one node per joint, the mesh node, the skin with its
// inverse bind matrices, and the scene (gltf_stages.h).
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {

BodyNodes addBodyNodes(GltfBuild& b, const Asset& asset, bool named_skin) {
  const Skeleton& s = asset.skeleton;
  const int k_count = int(s.names.size());
  const int base = int(b.model.nodes.size());
  for (int k = 0; k < k_count; ++k) {
    tinygltf::Node node;
    node.name = s.names[size_t(k)];
    node.translation = {s.rest_local(k, 0), s.rest_local(k, 1), s.rest_local(k, 2)};
    b.model.nodes.push_back(node);
  }
  for (int k = 1; k < k_count; ++k)
    b.model.nodes[size_t(base + s.parents[size_t(k)])].children.push_back(base + k);

  tinygltf::Node mesh_node;
  mesh_node.name = asset.name;
  mesh_node.mesh = int(b.model.meshes.size());  // the mesh addMesh adds next
  mesh_node.skin = int(b.model.skins.size());
  b.model.nodes.push_back(mesh_node);

  std::vector<float> ibm;
  tinygltf::Skin skin;
  if (named_skin) skin.name = asset.name;
  for (int k = 0; k < k_count; ++k) {
    // translation(-J_k), column-major: the translation is elements 12..14.
    std::vector<float> m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int c = 0; c < 3; ++c) m[size_t(12 + c)] = float(-s.rest_world(k, c));
    ibm.insert(ibm.end(), m.begin(), m.end());
    skin.joints.push_back(base + k);
  }
  skin.skeleton = base;
  skin.inverseBindMatrices = addFloats(b, ibm, TINYGLTF_TYPE_MAT4, 0, false);
  b.model.skins.push_back(skin);
  return BodyNodes{base, base + k_count};
}

void addScene(GltfBuild& b, const std::string& name, const std::vector<int>& roots) {
  tinygltf::Scene scene;
  scene.name = name;
  scene.nodes = roots;
  // Blender's importer drops asset.extras but keeps scene extras (custom properties).
  scene.extras = tinygltf::Value(
      tinygltf::Value::Object{{"smpl", tinygltf::Value(placeholderText(kScenePlaceholder))}});
  b.model.scenes.push_back(scene);
  b.model.defaultScene = 0;
}

void addNodesAndSkin(GltfBuild& b, const Asset& asset) {
  const BodyNodes nodes = addBodyNodes(b, asset, false);
  addScene(b, asset.name, {nodes.joint_base, nodes.mesh_node});
}

}  // namespace gltf
}  // namespace smpl
