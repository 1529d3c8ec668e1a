// glTF writer stage: one node per joint, the mesh node, the skin with its
// inverse bind matrices, and the scene (gltf_stages.h).
#include <tiny_gltf.h>

#include <vector>

#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {

// Joint nodes 0..K-1 in model order, then the mesh node K (a scene root, as
// the validator requires of skinned meshes), then the skin.
void addNodesAndSkin(GltfBuild& b, const Asset& asset) {
  const Skeleton& s = asset.skeleton;
  const int k_count = int(s.names.size());
  for (int k = 0; k < k_count; ++k) {
    tinygltf::Node node;
    node.name = s.names[size_t(k)];
    node.translation = {s.rest_local(k, 0), s.rest_local(k, 1), s.rest_local(k, 2)};
    b.model.nodes.push_back(node);
  }
  for (int k = 1; k < k_count; ++k)
    b.model.nodes[size_t(s.parents[size_t(k)])].children.push_back(k);

  tinygltf::Node mesh_node;
  mesh_node.name = asset.name;
  mesh_node.mesh = 0;
  mesh_node.skin = 0;
  b.model.nodes.push_back(mesh_node);

  std::vector<float> ibm;
  tinygltf::Skin skin;
  for (int k = 0; k < k_count; ++k) {
    // translation(-J_k), column-major: the translation is elements 12..14.
    std::vector<float> m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int c = 0; c < 3; ++c) m[size_t(12 + c)] = float(-s.rest_world(k, c));
    ibm.insert(ibm.end(), m.begin(), m.end());
    skin.joints.push_back(k);
  }
  skin.skeleton = 0;
  skin.inverseBindMatrices = addFloats(b, ibm, TINYGLTF_TYPE_MAT4, 0, false);
  b.model.skins.push_back(skin);

  tinygltf::Scene scene;
  scene.name = asset.name;
  scene.nodes = {0, k_count};
  // Blender's importer drops asset.extras but keeps scene extras (custom properties).
  scene.extras = tinygltf::Value(
      tinygltf::Value::Object{{"smpl", tinygltf::Value(placeholderText(kScenePlaceholder))}});
  b.model.scenes.push_back(scene);
  b.model.defaultScene = 0;
}

}  // namespace gltf
}  // namespace smpl
