// The bodies of a --scene FBX (fbx_scene_internal.h buildSceneBody): each
// built by the one-body builders in a context of its own over the shared
// objects, ids (under "body/<i>/") and connections.
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

// Hidden keys: each visibility change becomes two keys this far (in source
// frames) either side of the body's change time (half a frame before the
// changed frame), old value then new, with constant interpolation. Readers
// that honour it step; readers that interpolate every key linearly (Blender
// 3.4's io_scene_fbx bakes all keys as LINEAR) ramp only inside those
// 1/50 of a frame, so every frame time sees the right scale.
constexpr double kStepHalfWidthFrames = 0.01;

// The body's node: a Null Model named after the body, the parent of its
// skeleton (Blender makes it the body's armature object).
int64_t addBodyNode(SceneContext& ctx) {
  int64_t model = ctx.ids.id("model/body");
  addModelBody(ctx.addObject("Model", model, ctx.bodyName(), "Model", "Null"), 0, 0, 0);
  int64_t attr = ctx.ids.id("attribute/body");
  FbxNode& a = ctx.addObject("NodeAttribute", attr, ctx.bodyName(), "NodeAttribute", "Null");
  a.add("TypeFlags").addString("Null");
  ctx.connectOO(model, 0);
  ctx.connectOO(attr, model);
  return model;
}

// SceneBody's visibility (STEP keys of the node's scale) as Lcl Scaling keys.
void addVisibility(SceneContext& ctx, const SceneBody& body, int64_t node, int64_t layer,
                   double fps) {
  if (body.visibility.empty()) return;
  const double half = kStepHalfWidthFrames / fps;
  std::vector<double> seconds;
  std::vector<Eigen::Vector3d> scales;
  for (size_t i = 0; i < body.visibility.size(); ++i) {
    const Eigen::Vector3d now = Eigen::Vector3d::Constant(body.visibility[i]);
    if (i > 0) {
      seconds.push_back(body.visibility_times[i] - half);
      scales.push_back(scales.back());
    }
    seconds.push_back(body.visibility_times[i] + (i > 0 ? half : 0.0));
    scales.push_back(now);
  }
  addPropertyCurves(ctx, "visibility", "S", layer, node, "Lcl Scaling", seconds, scales, true);
}

}  // namespace

void buildSceneBody(SceneContext& shared, const SceneBody& body, size_t i, int64_t layer,
                    double fps) {
  SceneContext ctx(body.asset, shared.options);
  ctx.scale = shared.scale;
  ctx.takeShared(shared);
  ctx.ids.setPrefix("body/" + std::to_string(i) + "/");
  ctx.body_name = ctx.bodyName();
  ctx.mesh_name = ctx.body_name + "_mesh";
  ctx.ns = ctx.body_name + ":";
  ctx.skeleton_parent = addBodyNode(ctx);
  buildMeshObjects(ctx);
  buildSkeletonObjects(ctx);
  buildSkinObjects(ctx);
  buildMorphObjects(ctx);
  const std::vector<AnimationClip>& clips = body.asset.animations;
  for (size_t c = 0; c < clips.size(); ++c)
    addClipCurves(ctx, clips[c], "anim/" + std::to_string(c), layer, body.start);
  addVisibility(ctx, body, ctx.skeleton_parent, layer, fps);
  ctx.ids.setPrefix("");
  shared.takeShared(ctx);
}

}  // namespace fbx
}  // namespace smpl
