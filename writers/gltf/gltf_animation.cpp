// glTF writer stage: one animation per clip: joint rotations, root and joint
// translations, morph weights; float keys or, with --quantize-animation,
// normalised integers (gltf_stages.h).
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "writers/gltf/gltf_meshopt.h"
#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {
namespace {

// Rotation keys (x, y, z, w): float, or with --quantize-animation normalised
// SHORT (core glTF 2.0 animation samplers: c = round(32767 q), decoded
// max(c / 32767, -1)); with --meshopt the quantised keys are meshopt's
// QUATERNION filter of the same quaternions (16-bit components).
int addRotations(GltfBuild& b, const std::vector<float>& xyzw, bool quantize) {
  if (!quantize) return addFloats(b, xyzw, TINYGLTF_TYPE_VEC4, 0, false);
  std::vector<int16_t> q;
  MeshoptFilter filter = MeshoptFilter::None;
  if (b.meshopt) {
    q = quaternionFilter(xyzw);
    filter = MeshoptFilter::Quaternion;
  } else {
    q.resize(xyzw.size());
    for (size_t i = 0; i < xyzw.size(); ++i)
      q[i] = int16_t(std::nearbyint(std::max(-1.0f, std::min(1.0f, xyzw[i])) * 32767.0f));
  }
  const int view = addView(b, q.data(), q.size() * sizeof(int16_t), 0);
  markMeshopt(b, view, MeshoptMode::Attributes, 8, filter);
  return addAccessor(b, view, TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC4, xyzw.size() / 4,
                     true);
}

// Morph weight keys: float, or with --quantize-animation normalised
// UNSIGNED_SHORT (round(65535 w)) when every weight of the clip is in [0, 1]
// (split, unit, DMPL and animated-expression weights), SHORT (round(32767 w))
// when in [-1, 1]; otherwise (signed diagonal weights reach -2) float.
int addMorphWeights(GltfBuild& b, const MorphWeightTrack& track, bool quantize) {
  const float* w = track.data();  // row-major: frame by frame, as glTF stores them
  const size_t size = size_t(track.size());
  float lo = 0.f, hi = 0.f;
  for (size_t i = 0; i < size; ++i) lo = std::min(lo, w[i]), hi = std::max(hi, w[i]);
  if (!quantize || lo < -1.f || hi > 1.f)  // the asset's track, written where it is
    return addFloats(b, w, size, TINYGLTF_TYPE_SCALAR, 0, false, true);
  const bool positive = lo >= 0.f;
  // meshopt takes 4-byte elements: an odd count gets one zero of padding.
  std::vector<uint16_t> q(b.meshopt ? (size + 1) / 2 * 2 : size, 0);
  for (size_t i = 0; i < size; ++i)
    q[i] = positive ? uint16_t(std::nearbyint(double(w[i]) * 65535.0))
                    : uint16_t(int16_t(std::nearbyint(double(w[i]) * 32767.0)));
  const int view = addView(b, q.data(), q.size() * sizeof(uint16_t), 0);
  markMeshopt(b, view, MeshoptMode::Attributes, 4);
  return addAccessor(
      b, view, positive ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_SHORT,
      TINYGLTF_TYPE_SCALAR, size, true);
}

}  // namespace

void addChannel(tinygltf::Animation& anim, int input, int output, int node, const char* path,
                const char* interpolation) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = interpolation;
  anim.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = int(anim.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = path;
  anim.channels.push_back(channel);
}

Status addClipChannels(GltfBuild& b, const AnimationClip& clip, const BodyNodes& nodes,
                       double start, bool quantize, tinygltf::Animation* out) {
  tinygltf::Animation& anim = *out;
  std::vector<float> times;
  times.reserve(clip.times.size());
  for (double t : clip.times) times.push_back(float(t + start));
  const int input = addFloats(b, times, TINYGLTF_TYPE_SCALAR, 0, true);
  for (size_t k = 0; k < clip.rotations.size(); ++k) {
    const RotationTrack& track = clip.rotations[k];
    bool unit = true;  // as the bake stores them (asset.h): written where they are
    for (const Eigen::Quaternionf& q : track) {
      const double n = q.cast<double>().norm();
      if (!(n > 0) || !std::isfinite(n))
        return makeError("glTF writer: animation '" + clip.name + "': joint " + std::to_string(k) +
                         " has a zero or non-finite rotation");
      unit = unit && std::abs(n - 1.0) < 1e-6;
    }
    const float* keys = track.empty() ? nullptr : track.front().coeffs().data();
    if (unit && !quantize) {
      addChannel(anim, input,
                 addFloats(b, keys, 4 * track.size(), TINYGLTF_TYPE_VEC4, 0, false, true),
                 nodes.joint_base + int(k), "rotation");
      continue;
    }
    std::vector<float> xyzw;  // normalised (a hand-made clip) or to be quantised
    for (const Eigen::Quaternionf& q : track) {
      const Eigen::Vector4d c = q.coeffs().cast<double>();
      const double n = c.norm();
      for (int i = 0; i < 4; ++i) xyzw.push_back(unit ? q.coeffs()[i] : float(c[i] / n));
    }
    addChannel(anim, input, addRotations(b, xyzw, quantize), nodes.joint_base + int(k), "rotation");
  }
  if (!clip.root_translation.empty()) {
    std::vector<float> xyz;
    for (const Eigen::Vector3d& p : clip.root_translation)
      xyz.insert(xyz.end(), {float(p.x()), float(p.y()), float(p.z())});
    addChannel(anim, input, addFloats(b, xyz, TINYGLTF_TYPE_VEC3, 0, false), nodes.joint_base,
               "translation");
  }
  for (size_t k = 1; k < clip.joint_translations.size(); ++k) {  // DMPL joints, root bone
    if (clip.joint_translations[k].empty()) continue;            // at its rest offset
    std::vector<float> xyz;
    for (const Eigen::Vector3d& p : clip.joint_translations[k])
      xyz.insert(xyz.end(), {float(p.x()), float(p.y()), float(p.z())});
    addChannel(anim, input, addFloats(b, xyz, TINYGLTF_TYPE_VEC3, 0, false),
               nodes.joint_base + int(k), "translation");
  }
  if (clip.morph_weights.size() > 0) {  // T x 0 without morph targets: no channel
    addChannel(anim, input, addMorphWeights(b, clip.morph_weights, quantize), nodes.mesh_node,
               "weights");
  }
  return Status::success();
}

Status addAnimation(GltfBuild& b, const AnimationClip& clip, int mesh_node, bool quantize) {
  tinygltf::Animation anim;
  anim.name = clip.name;
  Status st = addClipChannels(b, clip, BodyNodes{0, mesh_node}, 0.0, quantize, &anim);
  if (!st) return st;
  b.model.animations.push_back(anim);
  return Status::success();
}

}  // namespace gltf
}  // namespace smpl
