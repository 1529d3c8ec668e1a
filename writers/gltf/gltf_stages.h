// Internal to the glTF writer: its stages, one file each, in the order
// gltf_writer.cpp's buildModel calls them. Not a public interface.
//   gltf_accessors.cpp  accessors over new bufferViews; row-major copies; extensions
//   gltf_streams.cpp    the mesh as glTF's flat streams (MeshStreams)
//   gltf_mesh.cpp       the mesh, its primitive (plain or Draco) and its morph targets
//   gltf_skeleton.cpp   joint nodes, the mesh node, the skin, the scene
//   gltf_animation.cpp  one animation per clip (float or quantised keys)
//   gltf_container.cpp  tinygltf's JSON, the metadata splice, the GLB, an external buffer
// Buffer layout helpers are in gltf_buffer.h, morph target encodings in
// gltf_morphs.h, Draco in gltf_draco.h, meshopt in gltf_meshopt.h.
#pragma once

#include <tiny_gltf.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/result.h"
#include "exporter/asset.h"
#include "writers/gltf/gltf_buffer.h"
#include "writers/gltf/gltf_draco.h"
#include "writers/writer.h"

namespace smpl {
namespace gltf {

// tinygltf 2.7 turns empty arrays inside extras into null and sorts object
// keys, so asset.extras.smpl and scenes[0].extras.smpl hold these placeholder
// strings while tinygltf writes, and the metadata text replaces them verbatim
// afterwards. The buffer's name placeholder marks where its length goes.
inline constexpr char kMetadataPlaceholder[] = "\"smpl-export:metadata:7c1e5a90\"";
inline constexpr char kScenePlaceholder[] = "\"smpl-export:scene-metadata:7c1e5a90\"";
inline constexpr char kBufferPlaceholder[] = "\"smpl-export:buffer:7c1e5a90\"";

// --- gltf_accessors.cpp ---
// A FLOAT accessor of `type` (TINYGLTF_TYPE_*) over a new view of `values`
// (view target `target`, 0: none); per-component min/max when `bounds`.
// in_place: `values` outlive the build (the asset's own array) and are written from
// where they are (addViewInPlace), not copied.
int addFloats(GltfBuild& b, const float* values, size_t size, int type, int target, bool bounds,
              bool in_place = false);
inline int addFloats(GltfBuild& b, const std::vector<float>& values, int type, int target,
                     bool bounds) {
  return addFloats(b, values.data(), values.size(), type, target, bounds);
}
// An integer accessor of `component_type` over a new view of `values`
// (uint8_t, uint16_t or uint32_t); meshopt-marked where the codec takes it.
template <class T>
int addIntegers(GltfBuild& b, const std::vector<T>& values, int component_type, int type,
                int target);
// JOINTS_n (4 per vertex): UNSIGNED_SHORT if `wide`, else UNSIGNED_BYTE.
int addJoints(GltfBuild& b, const std::vector<uint16_t>& joints, bool wide);
// The rows of `m` one after another (glTF's element order).
std::vector<float> rowMajor(const Eigen::MatrixXf& m);
// Adds `name` to extensionsUsed and extensionsRequired once.
void requireExtension(tinygltf::Model& model, const char* name);

// --- gltf_streams.cpp ---
// The streams of `m` (num_joints: the skeleton's joint count, checked
// against every influence). Errors: an invalid, out-of-range or all-zero
// skin row, naming the vertex.
Result<MeshStreams> meshStreams(const SkinnedMesh& m, int num_joints);
// Whether `v_count` vertices need UNSIGNED_INT indices (65535 is
// UNSIGNED_SHORT's primitive restart value, so it must not occur).
bool wideIndices(size_t v_count);

// --- gltf_mesh.cpp ---
// Mesh 0 of the asset: one triangle primitive (Draco with options.draco), its
// morph targets (sparse or quantised per the options and the asset's marks),
// rest weights and extras.targetNames.
Status addMesh(GltfBuild& b, const Asset& asset, const WriterOptions& options);

// --- gltf_skeleton.cpp ---
// Where one body's nodes are: joints joint_base .. joint_base + K - 1 in
// model order (joint_base is the skeleton root), then its mesh node.
struct BodyNodes {
  int joint_base = 0;
  int mesh_node = 0;
};
// One body appended: its joint nodes with their rest translations (metres),
// its mesh node (a scene root, as the validator requires of skinned meshes;
// it names the mesh the next addMesh adds) and its skin (inverse bind
// matrices translation(-J_k); named after the asset when `named_skin`).
BodyNodes addBodyNodes(GltfBuild& b, const Asset& asset, bool named_skin);
// Scene 0 `name` with `roots`, whose extras.smpl holds kScenePlaceholder.
void addScene(GltfBuild& b, const std::string& name, const std::vector<int>& roots);
// The one-body file: addBodyNodes (nodes 0..K-1, mesh node K, skin 0) and
// scene 0 with roots {0, K}.
void addNodesAndSkin(GltfBuild& b, const Asset& asset);

// --- gltf_animation.cpp ---
// A sampler (`interpolation`: "LINEAR" or "STEP") and its channel on `path` of `node`.
void addChannel(tinygltf::Animation& anim, int input, int output, int node, const char* path,
                const char* interpolation = "LINEAR");
// The channels of `clip` on the body at `nodes` (times in seconds plus
// `start`; LINEAR samplers), morph weights on its mesh node; `quantize`:
// normalised integer keys where the values allow (--quantize-animation).
// Errors: a zero or non-finite rotation.
Status addClipChannels(GltfBuild& b, const AnimationClip& clip, const BodyNodes& nodes,
                       double start, bool quantize, tinygltf::Animation* anim);
// One animation of `clip` on the one-body file's nodes (joints from 0,
// morph weights on node `mesh_node`), as addClipChannels.
Status addAnimation(GltfBuild& b, const AnimationClip& clip, int mesh_node, bool quantize);

// --- gltf_scene.cpp ---
// The model of a --scene file (exporter/scene_asset.h): per body, in order,
// its body node (named after it, parent of its skeleton root), then its
// joint nodes, mesh node and mesh (both named <body>_mesh), skin, morph targets
// as one-body files have them (addBodyNodes, addMesh); one animation holding
// every body's clip at its start, the STEP scale keys on the body node that
// hide it outside its frames, and the camera node's keys; the camera node
// last. Errors: those of the stages.
Status addSceneContent(GltfBuild& b, const SceneAsset& scene, const WriterOptions& options);

// --- gltf_container.cpp ---
// A placeholder's string value (without its quotes).
std::string placeholderText(const char* quoted);
// Replaces `placeholder` (which must occur exactly once) by `text`.
Status splice(std::string& json, const std::string& placeholder, const std::string& text);
// The metadata text over both metadata placeholders (asset and scene extras).
Status spliceMetadata(std::string& json, const std::string& metadata);
// GLB: header, JSON chunk (space-padded), BIN chunk written once from `bin`.
std::string glbHead(std::string json, size_t bin_size);
// tinygltf's JSON of `model`: compact (the GLB's JSON chunk) or indented (.gltf).
Result<std::string> serializeJson(tinygltf::Model& model, bool binary);
// A pretty-printed .gltf whose (empty, placeholder-named) buffer becomes the
// external file `uri` of `size` bytes.
Status pointBufferAt(std::string& json, const std::string& uri, size_t size);

}  // namespace gltf
}  // namespace smpl
