// Animation clips as AnimationStack -> AnimationLayer -> AnimationCurveNode
// -> AnimationCurve (fbx_scene_internal.h): Euler XYZ rotation curves per
// joint, translation curves on the root joint, DeformPercent curves per
// blend shape channel. Keys are sampled frames with linear interpolation.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/math/libm.h"
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One solution of R = Rz(z) * Ry(y) * Rx(x); in gimbal lock x is kept at
// `x_hint` and z absorbs the rest.
Eigen::Vector3d eulerXYZ(const Eigen::Matrix3d& r, double x_hint) {
  double y = libm::asin(std::max(-1.0, std::min(1.0, -r(2, 0))));
  if (std::abs(libm::cos(y)) > 1e-9)
    return {libm::atan2(r(2, 1), r(2, 2)), y, libm::atan2(r(1, 0), r(0, 0))};
  double combined = libm::atan2(-r(0, 1), r(1, 1));  // z - x at y=+90, z + x at y=-90
  return {x_hint, y, y > 0 ? combined + x_hint : combined - x_hint};
}

double nearestWrap(double angle, double reference) {
  return angle + 2 * kPi * std::round((reference - angle) / (2 * kPi));
}

Eigen::Vector3d wrapTowards(const Eigen::Vector3d& e, const Eigen::Vector3d& prev) {
  return {nearestWrap(e.x(), prev.x()), nearestWrap(e.y(), prev.y()), nearestWrap(e.z(), prev.z())};
}

// A clip's key times (FBX KTime) and their KeyTime array, encoded once for
// all of its curves (one copy in memory, compressed once).
struct KeyTimes {
  std::vector<int64_t> ktime;
  FbxProperty array;  // fbxSharedInt64Array(ktime)
  size_t size() const { return ktime.size(); }
  bool empty() const { return ktime.empty(); }
};

FbxNode& addCurveNode(SceneContext& ctx, int64_t id, const char* name, int64_t layer,
                      int64_t target, const char* property) {
  FbxNode& n = ctx.addObject("AnimationCurveNode", id, name, "AnimCurveNode", "");
  ctx.connectOO(id, layer);
  ctx.connectOP(id, target, property);
  return n;
}

// KeyAttrFlags: linear interpolation (0x4) with the usual auto-tangent bits;
// constant (0x2): a key holds until the next.
constexpr int32_t kLinearKeys = 0x4 | 0x100 | 0x2000 | 0x4000;
constexpr int32_t kConstantKeys = 0x2;

void addCurve(SceneContext& ctx, int64_t id, int64_t curve_node, const char* channel,
              const KeyTimes& times, const std::vector<float>& values,
              int32_t flags = kLinearKeys) {
  FbxNode& c = ctx.addObject("AnimationCurve", id, "", "AnimCurve", "");
  c.add("Default").addDouble(values.empty() ? 0.0 : values[0]);
  c.add("KeyVer").addInt32(4008);
  c.add("KeyTime").addShared(times.array);
  c.add("KeyValueFloat").addFloatArray(values);
  // One attribute shared by all keys; data = slopes 0, default tangent
  // weights 1/3.
  c.add("KeyAttrFlags").addInt32Array({flags});
  const int32_t weights_bits = (3333 << 16) | 3333;
  float weights;
  std::memcpy(&weights, &weights_bits, sizeof weights);
  c.add("KeyAttrDataFloat").addFloatArray({0.0f, 0.0f, weights, 0.0f});
  c.add("KeyAttrRefCount").addInt32Array({static_cast<int32_t>(times.size())});
  ctx.connectOP(id, curve_node, std::string("d|") + channel);
}

// A 3-channel curve node (d|X, d|Y, d|Z) with its three curves.
void addVectorCurves(SceneContext& ctx, const std::string& key, const char* name, int64_t layer,
                     int64_t target, const char* property, const KeyTimes& times,
                     const std::vector<Eigen::Vector3d>& values, int32_t flags = kLinearKeys) {
  int64_t node_id = ctx.ids.id(key);
  FbxNode& node = addCurveNode(ctx, node_id, name, layer, target, property);
  FbxNode& p = node.add("Properties70");
  addP(p, "d", "Compound", "", "");
  const char* channels[] = {"X", "Y", "Z"};
  for (int c = 0; c < 3; ++c)
    pNumber(p, std::string("d|") + channels[c], values.empty() ? 0.0 : values[0][c], true);
  for (int c = 0; c < 3; ++c) {
    std::vector<float> v(values.size());
    for (size_t i = 0; i < values.size(); ++i) v[i] = static_cast<float>(values[i][c]);
    addCurve(ctx, ctx.ids.id(key + "/" + channels[c]), node_id, channels[c], times, v, flags);
  }
}

void addMorphCurves(SceneContext& ctx, const AnimationClip& clip, const std::string& prefix,
                    int64_t layer, const KeyTimes& times) {
  for (Eigen::Index t = 0; t < clip.morph_weights.cols(); ++t) {
    std::string key = prefix + "/morph/" + std::to_string(t);
    int64_t node_id = ctx.ids.id(key);
    std::vector<float> percent(times.size());
    for (size_t i = 0; i < times.size(); ++i)
      percent[i] = clip.morph_weights(Eigen::Index(i), t) * 100.0f;
    FbxNode& node =
        addCurveNode(ctx, node_id, "DeformPercent", layer, ctx.blend_channels[t], "DeformPercent");
    FbxNode& p = node.add("Properties70");
    addP(p, "d", "Compound", "", "");
    pNumber(p, "d|DeformPercent", percent.empty() ? 0.0 : percent[0], true);
    addCurve(ctx, ctx.ids.id(key + "/curve"), node_id, "DeformPercent", times, percent);
  }
}

KeyTimes keyTimes(const std::vector<double>& seconds, double offset) {
  KeyTimes times;
  times.ktime.resize(seconds.size());
  for (size_t i = 0; i < times.size(); ++i) times.ktime[i] = secondsToKTime(offset + seconds[i]);
  times.array = fbxSharedInt64Array(times.ktime);
  return times;
}

void addClipKeys(SceneContext& ctx, const AnimationClip& clip, const std::string& prefix,
                 int64_t layer, const KeyTimes& times) {
  if (times.empty()) return;
  for (size_t k = 0; k < clip.rotations.size(); ++k) {
    std::vector<Eigen::Vector3d> euler = continuousEulerXYZDegrees(clip.rotations[k]);
    addVectorCurves(ctx, prefix + "/R/" + std::to_string(k), "R", layer, ctx.joint_models[k],
                    "Lcl Rotation", times, euler);
  }
  if (!clip.root_translation.empty()) {
    std::vector<Eigen::Vector3d> t(clip.root_translation.size());
    for (size_t i = 0; i < t.size(); ++i) t[i] = clip.root_translation[i] * ctx.scale;
    addVectorCurves(ctx, prefix + "/T/0", "T", layer, ctx.joint_models[0], "Lcl Translation", times,
                    t);
  }
  for (size_t k = 1; k < clip.joint_translations.size(); ++k) {  // DMPL joints, root bone
    if (clip.joint_translations[k].empty()) continue;            // at its rest offset
    std::vector<Eigen::Vector3d> t(clip.joint_translations[k].size());
    for (size_t i = 0; i < t.size(); ++i) t[i] = clip.joint_translations[k][i] * ctx.scale;
    addVectorCurves(ctx, prefix + "/T/" + std::to_string(k), "T", layer, ctx.joint_models[k],
                    "Lcl Translation", times, t);
  }
  if (clip.morph_weights.size() > 0) addMorphCurves(ctx, clip, prefix, layer, times);
}

void addClip(SceneContext& ctx, const AnimationClip& clip, size_t index) {
  const std::string prefix = "anim/" + std::to_string(index);
  KeyTimes times = keyTimes(clip.times, 0.0);
  int64_t start = times.empty() ? 0 : times.ktime.front();
  int64_t stop = times.empty() ? 0 : times.ktime.back();
  int64_t layer = addAnimationLayer(ctx, prefix, clip.name, start, stop);
  addClipKeys(ctx, clip, prefix, layer, times);
}

}  // namespace

std::vector<Eigen::Vector3d> continuousEulerXYZDegrees(const RotationTrack& q) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(q.size());
  Eigen::Vector3d prev(0, 0, 0);
  for (const Eigen::Quaternionf& rotation : q) {
    Eigen::Matrix3d r = rotation.cast<double>().normalized().toRotationMatrix();
    Eigen::Vector3d a = wrapTowards(eulerXYZ(r, prev.x()), prev);
    // The other solution of the same rotation: (x + pi, pi - y, z + pi).
    Eigen::Vector3d b = wrapTowards(Eigen::Vector3d(a.x() + kPi, kPi - a.y(), a.z() + kPi), prev);
    prev = (a - prev).squaredNorm() <= (b - prev).squaredNorm() ? a : b;
    out.push_back(prev);
  }
  for (Eigen::Vector3d& e : out) e *= 180.0 / kPi;
  return out;
}

int64_t addAnimationLayer(SceneContext& ctx, const std::string& key, const std::string& name,
                          int64_t start, int64_t stop) {
  int64_t stack = ctx.ids.id(key + "/stack");
  FbxNode& s = ctx.addObject("AnimationStack", stack, name, "AnimStack", "");
  FbxNode& sp = s.add("Properties70");
  pTime(sp, "LocalStart", start);
  pTime(sp, "LocalStop", stop);
  pTime(sp, "ReferenceStart", start);
  pTime(sp, "ReferenceStop", stop);
  int64_t layer = ctx.ids.id(key + "/layer");
  ctx.addObject("AnimationLayer", layer, name, "AnimLayer", "").add("Properties70");
  ctx.connectOO(layer, stack);
  return layer;
}

void addClipCurves(SceneContext& ctx, const AnimationClip& clip, const std::string& prefix,
                   int64_t layer, double offset) {
  addClipKeys(ctx, clip, prefix, layer, keyTimes(clip.times, offset));
}

void addPropertyCurves(SceneContext& ctx, const std::string& key, const char* name, int64_t layer,
                       int64_t target, const char* property, const std::vector<double>& seconds,
                       const std::vector<Eigen::Vector3d>& values, bool constant) {
  addVectorCurves(ctx, key, name, layer, target, property, keyTimes(seconds, 0.0), values,
                  constant ? kConstantKeys : kLinearKeys);
}

void buildAnimationObjects(SceneContext& ctx) {
  for (size_t i = 0; i < ctx.asset.animations.size(); ++i) addClip(ctx, ctx.asset.animations[i], i);
}

}  // namespace fbx
}  // namespace smpl
