// glTF writer stage: a --scene file's content (gltf_stages.h): every body as
// a one-body file has it below a node of its own, one animation for all of
// them on the shared timeline, the STEP scale keys that hide a body outside
// its frames, and the animated camera.
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "exporter/validate_asset.h"
#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {
namespace {

// Clipping planes of the scene camera (metres): the files carry none.
constexpr double kCameraNear = 0.01;
constexpr double kCameraFar = 1000.0;

// The body's own node (named after it), parent of its skeleton: clients
// that make one armature per common ancestor of a skin's joints (Blender)
// make one per body, and hiding the body is one scale on it.
int addBodyRoot(GltfBuild& b, const std::string& name) {
  tinygltf::Node node;
  node.name = name;
  b.model.nodes.push_back(node);
  return int(b.model.nodes.size()) - 1;
}

// `body`'s visibility as STEP scale keys on its body node: scale 0
// collapses every joint below it, so the skinned mesh becomes one point.
void addVisibility(GltfBuild& b, const SceneBody& body, int root, tinygltf::Animation* anim) {
  if (body.visibility.empty()) return;
  std::vector<float> times, scales;
  for (size_t i = 0; i < body.visibility.size(); ++i) {
    times.push_back(float(body.visibility_times[i]));
    scales.insert(scales.end(), 3, body.visibility[i]);
  }
  const int input = addFloats(b, times, TINYGLTF_TYPE_SCALAR, 0, true);
  addChannel(*anim, input, addFloats(b, scales, TINYGLTF_TYPE_VEC3, 0, false), root, "scale",
             "STEP");
}

// The camera (camera 0) on a node of its own, placed at its first key and
// animated (LINEAR translation and rotation keys).
int addCameraNode(GltfBuild& b, const SceneCameraClip& c, tinygltf::Animation* anim) {
  tinygltf::Camera camera;
  camera.name = "camera";
  camera.type = "perspective";
  camera.perspective.yfov = c.yfov;
  camera.perspective.aspectRatio = c.aspect;  // 0: not written
  camera.perspective.znear = kCameraNear;
  camera.perspective.zfar = kCameraFar;
  b.model.cameras.push_back(camera);
  std::vector<float> times, xyz, xyzw;
  for (size_t f = 0; f < c.times.size(); ++f) {
    times.push_back(float(c.times[f]));
    for (int i = 0; i < 3; ++i) xyz.push_back(float(c.position[f][i]));
    for (int i = 0; i < 4; ++i) xyzw.push_back(c.rotation[f].coeffs()[i]);
  }
  tinygltf::Node node;
  node.name = "camera";
  node.camera = int(b.model.cameras.size()) - 1;
  node.translation = {xyz[0], xyz[1], xyz[2]};
  node.rotation = {xyzw[0], xyzw[1], xyzw[2], xyzw[3]};
  b.model.nodes.push_back(node);
  const int at = int(b.model.nodes.size()) - 1;
  const int input = addFloats(b, times, TINYGLTF_TYPE_SCALAR, 0, true);
  addChannel(*anim, input, addFloats(b, xyz, TINYGLTF_TYPE_VEC3, 0, false), at, "translation");
  addChannel(*anim, input, addFloats(b, xyzw, TINYGLTF_TYPE_VEC4, 0, false), at, "rotation");
  return at;
}

}  // namespace

Status addSceneContent(GltfBuild& b, const SceneAsset& scene, const WriterOptions& options) {
  std::vector<BodyNodes> nodes;
  std::vector<int> body_roots, roots;
  for (const SceneBody& body : scene.bodies) {
    // The same rules as a one-body file (exporter/validate_asset.h), per body.
    if (Status st = validateAsset(body.asset); !st)
      return makeError("body '" + body.asset.name + "': " + st.message());
    const int root = addBodyRoot(b, body.asset.name);
    const BodyNodes n = addBodyNodes(b, body.asset, true);
    b.model.nodes[size_t(root)].children.push_back(n.joint_base);
    if (Status st = addMesh(b, body.asset, options); !st) return st;
    // The skinned mesh node stays a scene root (the validator requires it); it
    // and its mesh are named apart from the body node, so that clients that
    // name objects after either (Blender: after the mesh) keep every name.
    b.model.nodes[size_t(n.mesh_node)].name = body.asset.name + "_mesh";
    b.model.meshes.back().name = body.asset.name + "_mesh";
    roots.insert(roots.end(), {root, n.mesh_node});
    body_roots.push_back(root);
    nodes.push_back(n);
  }
  tinygltf::Animation anim;
  anim.name = scene.name;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const SceneBody& body = scene.bodies[i];
    for (const AnimationClip& clip : body.asset.animations)
      if (Status st =
              addClipChannels(b, clip, nodes[i], body.start, options.quantize_animation, &anim);
          !st)
        return st;
    addVisibility(b, body, body_roots[i], &anim);
  }
  if (scene.camera.present()) roots.push_back(addCameraNode(b, scene.camera, &anim));
  if (!anim.channels.empty()) b.model.animations.push_back(anim);
  addScene(b, scene.name, roots);
  return Status::success();
}

}  // namespace gltf
}  // namespace smpl
