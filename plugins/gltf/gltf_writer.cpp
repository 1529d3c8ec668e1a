// glTF 2.0 / GLB writer. Translates an Asset into a tinygltf::Model (one
// buffer, one 4-byte aligned bufferView per accessor); tinygltf writes the
// JSON, and the GLB container and binary chunk are laid out here
// (gltf_buffer.h) so the buffer is copied once. Morph targets may be sparse or
// quantized (gltf_morphs.h, morph_scales.h), the base mesh Draco-compressed
// (gltf_draco.h), animation outputs normalised integers (--quantize-animation)
// and the views meshopt-compressed (gltf_meshopt.h). Computes nothing about the body: it only
// converts layouts (row-major floats, glTF's v = 1 - v, 4-slot skin sets) and tidies float rounding
// so the Khronos validator reports no warnings.
#include "plugins/gltf/gltf_writer.h"

#include <tiny_gltf.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <sstream>

#include "exporter/metadata_json.h"
#include "exporter/validate_asset.h"
#include "plugins/gltf/gltf_buffer.h"
#include "plugins/gltf/gltf_draco.h"
#include "plugins/gltf/gltf_meshopt.h"
#include "plugins/gltf/gltf_morphs.h"

namespace smpl {
namespace {

// tinygltf 2.7 turns empty arrays inside extras into null and sorts object
// keys, so asset.extras.smpl and scenes[0].extras.smpl hold these placeholder
// strings while tinygltf writes, and the metadata text replaces them verbatim
// afterwards. The buffer's name placeholder marks where its length goes.
const char kMetadataPlaceholder[] = "\"smpl-export:metadata:7c1e5a90\"";
const char kScenePlaceholder[] = "\"smpl-export:scene-metadata:7c1e5a90\"";
const char kBufferPlaceholder[] = "\"smpl-export:buffer:7c1e5a90\"";

// The placeholder's string value (without its quotes).
std::string placeholderText(const char* quoted) {
  const std::string q(quoted);
  return q.substr(1, q.size() - 2);
}

// Upper bound of the buffer size, reserved once so appending never reallocates.
size_t estimatedBufferBytes(const Asset& a) {
  const size_t v = size_t(a.mesh.positions.rows());
  size_t n = v * (12 + 12 + 8 + size_t(a.mesh.joints.cols() + 3) / 4 * 24) +
             size_t(a.mesh.triangles.size()) * 4 + a.skeleton.names.size() * 64 + 64 +
             a.mesh.morph_targets.size() * (v * 16 + 8);
  for (const AnimationClip& c : a.animations)
    n += c.times.size() *
         (4 + 16 * c.rotations.size() + 12 + 4 * size_t(c.morph_weights.cols()) + 16);
  return n;
}

constexpr size_t kMaxBufferBytes = 0xF0000000u;  // GLB lengths are uint32

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 1;
  }
}

// Float accessor; bounds (per-component min/max) where glTF requires them.
int addFloats(GltfBuild& b, const std::vector<float>& values, int type, int target, bool bounds) {
  const int n = componentCount(type);
  const size_t count = values.size() / size_t(n);
  const int view = addView(b, values.data(), values.size() * sizeof(float), target);
  markMeshopt(b, view, MeshoptMode::Attributes, 4 * n);
  const int accessor = addAccessor(b, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, count);
  tinygltf::Accessor& a = b.model.accessors[size_t(accessor)];
  if (bounds && count > 0) floatBounds(values.data(), count, n, &a.minValues, &a.maxValues);
  return accessor;
}

// Integer accessor; meshopt takes index lists (INDICES) and 4-byte-multiple elements.
template <class T>
int addIntegers(GltfBuild& b, const std::vector<T>& values, int component_type, int type,
                int target) {
  const int view = addView(b, values.data(), values.size() * sizeof(T), target);
  const int element = int(sizeof(T)) * componentCount(type);
  if (target == TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER)
    markMeshopt(b, view, MeshoptMode::Indices, int(sizeof(T)));
  else if (element % 4 == 0)
    markMeshopt(b, view, MeshoptMode::Attributes, element);
  return addAccessor(b, view, component_type, type, values.size() / size_t(componentCount(type)));
}

// JOINTS_n in the narrowest type that holds every joint index.
int addJoints(GltfBuild& b, const std::vector<uint16_t>& joints, bool wide) {
  if (!wide) {
    std::vector<uint8_t> narrow(joints.begin(), joints.end());
    return addIntegers(b, narrow, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4,
                       TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  return addIntegers(b, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4,
                     TINYGLTF_TARGET_ARRAY_BUFFER);
}

std::vector<float> rowMajor(const Eigen::MatrixXf& m) {
  std::vector<float> out(size_t(m.rows() * m.cols()));
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) out[size_t(r * m.cols() + c)] = m(r, c);
  return out;
}

// Unit length in float (the validator checks it); a zero normal, which only
// an unreferenced or degenerate vertex has, becomes +Y rather than invalid.
std::vector<float> unitNormals(const Eigen::MatrixXf& normals) {
  std::vector<float> out = rowMajor(normals);
  for (size_t i = 0; i < out.size(); i += 3) {
    double len = std::sqrt(double(out[i]) * out[i] + double(out[i + 1]) * out[i + 1] +
                           double(out[i + 2]) * out[i + 2]);
    for (int c = 0; c < 3; ++c)
      out[i + c] = len > 0 ? float(out[i + c] / len) : (c == 1 ? 1.f : 0.f);
  }
  return out;
}

std::vector<float> flippedUvs(const Eigen::MatrixXf& uvs) {
  std::vector<float> out = rowMajor(uvs);
  for (size_t i = 1; i < out.size(); i += 2) out[i] = 1.0f - out[i];
  return out;
}

// The validator's weight sum: float32 accumulation over component c of every
// set in turn (WEIGHTS_0[c], WEIGHTS_1[c], ...), tolerance 2e-7 per nonzero.
bool validatorNormalised(const std::vector<float>& w, int sets) {
  float sum = 0.f;
  int nonzero = 0;
  for (int c = 0; c < 4; ++c)
    for (int s = 0; s < sets; ++s)
      if (w[size_t(4 * s + c)] != 0.f) {
        sum = float(sum + w[size_t(4 * s + c)]);
        ++nonzero;
      }
  return std::fabs(double(sum) - 1.0) <= 2e-7 * nonzero;
}

// One vertex's influences in 4*sets slots: duplicates merged, zero-weight
// slots on joint 0 (the validator warns on a nonzero joint with zero weight),
// renormalised in float until the validator's sum check passes.
Status packVertexSkin(const SkinnedMesh& m, Eigen::Index v, int num_joints, int sets,
                      std::vector<uint16_t>& joints, std::vector<float>& weights) {
  const int slots = 4 * sets;
  std::vector<double> w(size_t(slots), 0.0);
  joints.assign(size_t(slots), 0);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < m.joints.cols(); ++i) {
    const int j = m.joints(v, i);
    const double wi = m.weights(v, i);
    if (!std::isfinite(wi) || wi < 0)
      return makeError("glTF writer: vertex " + std::to_string(v) + " has invalid skin weight");
    if (j < 0 || j >= num_joints)
      return makeError("glTF writer: vertex " + std::to_string(v) + " uses joint " +
                       std::to_string(j) + "; the skeleton has " + std::to_string(num_joints));
    if (wi == 0) continue;
    int slot = int(i);
    for (int k = 0; k < int(i); ++k)
      if (w[size_t(k)] > 0 && joints[size_t(k)] == j) slot = k;
    joints[size_t(slot)] = uint16_t(j);
    w[size_t(slot)] += wi;
    sum += wi;
  }
  if (!(sum > 0))
    return makeError("glTF writer: vertex " + std::to_string(v) + " has no positive skin weight");
  weights.assign(size_t(slots), 0.f);
  int largest = 0;
  for (int k = 0; k < slots; ++k) {
    weights[size_t(k)] = float(w[size_t(k)] / sum);
    if (w[size_t(k)] > w[size_t(largest)]) largest = k;
  }
  for (int round = 0; round < 4 && !validatorNormalised(weights, sets); ++round) {
    double total = 0.0;
    for (int c = 0; c < 4; ++c)
      for (int s = 0; s < sets; ++s) total = float(total + weights[size_t(4 * s + c)]);
    weights[size_t(largest)] = float(weights[size_t(largest)] + (1.0 - total));
  }
  return Status::success();
}

// JOINTS_n / WEIGHTS_n streams, ceil(M/4) sets.
Status packSkin(const SkinnedMesh& m, int num_joints, MeshStreams* out) {
  const int sets = int((m.joints.cols() + 3) / 4);
  const size_t v_count = size_t(m.positions.rows());
  out->joints.assign(size_t(sets), std::vector<uint16_t>(4 * v_count));
  out->weights.assign(size_t(sets), std::vector<float>(4 * v_count));
  out->wide_joints = num_joints >= 256;
  std::vector<uint16_t> vj;
  std::vector<float> vw;
  for (size_t v = 0; v < v_count; ++v) {
    Status st = packVertexSkin(m, Eigen::Index(v), num_joints, sets, vj, vw);
    if (!st) return st;
    for (int s = 0; s < sets; ++s)
      for (int c = 0; c < 4; ++c) {
        out->joints[size_t(s)][4 * v + size_t(c)] = vj[size_t(4 * s + c)];
        out->weights[size_t(s)][4 * v + size_t(c)] = vw[size_t(4 * s + c)];
      }
  }
  return Status::success();
}

Result<MeshStreams> meshStreams(const SkinnedMesh& m, int num_joints) {
  MeshStreams out;
  out.vertices = size_t(m.positions.rows());
  out.positions = rowMajor(m.positions);
  out.normals = unitNormals(m.normals);
  if (m.uvs.rows() > 0) out.uvs = flippedUvs(m.uvs);
  Status st = packSkin(m, num_joints, &out);
  if (!st) return st.error();
  out.indices.reserve(size_t(m.triangles.size()));
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c) out.indices.push_back(uint32_t(m.triangles(f, c)));
  return out;
}

// 65535 is the primitive restart value of UNSIGNED_SHORT, so it must not occur.
bool wideIndices(size_t v_count) { return v_count >= 65535; }

// The streams as ordinary accessors, one bufferView each.
void addPlainAttributes(GltfBuild& b, const MeshStreams& s, tinygltf::Primitive& prim) {
  prim.attributes["POSITION"] =
      addFloats(b, s.positions, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, true);
  prim.attributes["NORMAL"] =
      addFloats(b, s.normals, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  if (!s.uvs.empty())
    prim.attributes["TEXCOORD_0"] =
        addFloats(b, s.uvs, TINYGLTF_TYPE_VEC2, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  for (size_t i = 0; i < s.joints.size(); ++i) {
    prim.attributes["JOINTS_" + std::to_string(i)] = addJoints(b, s.joints[i], s.wide_joints);
    prim.attributes["WEIGHTS_" + std::to_string(i)] =
        addFloats(b, s.weights[i], TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  if (!wideIndices(s.vertices)) {
    std::vector<uint16_t> narrow(s.indices.begin(), s.indices.end());
    prim.indices = addIntegers(b, narrow, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                               TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  } else {
    prim.indices = addIntegers(b, s.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                               TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
}

// KHR_draco_mesh_compression: the accessors keep count, type and bounds but
// have no bufferView; the extension names the compressed view and the ids.
Status addDracoAttributes(GltfBuild& b, const MeshStreams& s, tinygltf::Primitive& prim) {
  Result<DracoBlob> blob = encodeDraco(s);
  if (!blob) return blob.error();
  const int view = addView(b, blob->bytes.data(), blob->bytes.size(), 0);
  const size_t v = s.vertices;
  const int pos = addAccessor(b, -1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v);
  tinygltf::Accessor& p = b.model.accessors[size_t(pos)];
  floatBounds(s.positions.data(), v, 3, &p.minValues, &p.maxValues);
  prim.attributes["POSITION"] = pos;
  prim.attributes["NORMAL"] =
      addAccessor(b, -1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v);
  if (!s.uvs.empty())
    prim.attributes["TEXCOORD_0"] =
        addAccessor(b, -1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, v);
  const int joint_type = s.wide_joints ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                       : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  for (size_t i = 0; i < s.joints.size(); ++i) {
    prim.attributes["JOINTS_" + std::to_string(i)] =
        addAccessor(b, -1, joint_type, TINYGLTF_TYPE_VEC4, v);
    prim.attributes["WEIGHTS_" + std::to_string(i)] =
        addAccessor(b, -1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, v);
  }
  prim.indices = addAccessor(b, -1,
                             wideIndices(v) ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT
                                            : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                             TINYGLTF_TYPE_SCALAR, s.indices.size());
  tinygltf::Value::Object ids;
  for (const auto& a : blob->attributes) ids[a.first] = tinygltf::Value(a.second);
  tinygltf::Value::Object ext{{"bufferView", tinygltf::Value(view)},
                              {"attributes", tinygltf::Value(ids)}};
  prim.extensions["KHR_draco_mesh_compression"] = tinygltf::Value(ext);
  return Status::success();
}

void requireExtension(tinygltf::Model& model, const char* name) {
  for (const std::string& e : model.extensionsUsed)
    if (e == name) return;
  model.extensionsUsed.push_back(name);
  model.extensionsRequired.push_back(name);
}

// Morph targets in the encoding of `options`; targets the asset marks
// quantized (exportAsset, morph_scales.h) as normalised int16.
void addMorphTargets(GltfBuild& b, const SkinnedMesh& m, const WriterOptions& options,
                     tinygltf::Primitive& prim, tinygltf::Mesh& mesh) {
  tinygltf::Value::Array names;
  for (size_t n = 0; n < m.morph_targets.size(); ++n) {
    const MorphTarget& t = m.morph_targets[n];
    MorphEncoding e;
    e.epsilon = options.morph_epsilon;
    e.quantized = t.quantized;
    e.peak = t.peak;
    if (e.quantized) requireExtension(b.model, "KHR_mesh_quantization");
    prim.targets.push_back({{"POSITION", addMorphTarget(b, t.deltas, e)}});
    mesh.weights.push_back(
        double(t.rest_weight));  // non-zero only for the unit corrective encoding
    names.emplace_back(t.name);
  }
  // An empty targetNames would serialise as null (tinygltf), so omit it.
  if (!names.empty())
    mesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(names)}});
}

Status addMesh(GltfBuild& b, const Asset& asset, const WriterOptions& options) {
  Result<MeshStreams> streams = meshStreams(asset.mesh, int(asset.skeleton.names.size()));
  if (!streams) return streams.error();
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  if (options.draco) {
    Status st = addDracoAttributes(b, *streams, prim);
    if (!st) return st;
    requireExtension(b.model, "KHR_draco_mesh_compression");
  } else {
    addPlainAttributes(b, *streams, prim);
  }
  tinygltf::Mesh mesh;
  mesh.name = asset.name;
  addMorphTargets(b, asset.mesh, options, prim, mesh);
  mesh.primitives.push_back(prim);
  b.model.meshes.push_back(mesh);
  return Status::success();
}

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

void addChannel(tinygltf::Animation& anim, int input, int output, int node, const char* path) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  anim.samplers.push_back(sampler);
  tinygltf::AnimationChannel channel;
  channel.sampler = int(anim.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = path;
  anim.channels.push_back(channel);
}

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
int addMorphWeights(GltfBuild& b, const std::vector<float>& w, bool quantize) {
  float lo = 0.f, hi = 0.f;
  for (float v : w) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!quantize || lo < -1.f || hi > 1.f) return addFloats(b, w, TINYGLTF_TYPE_SCALAR, 0, false);
  const bool positive = lo >= 0.f;
  // meshopt takes 4-byte elements: an odd count gets one zero of padding.
  std::vector<uint16_t> q(b.meshopt ? (w.size() + 1) / 2 * 2 : w.size(), 0);
  for (size_t i = 0; i < w.size(); ++i)
    q[i] = positive ? uint16_t(std::nearbyint(double(w[i]) * 65535.0))
                    : uint16_t(int16_t(std::nearbyint(double(w[i]) * 32767.0)));
  const int view = addView(b, q.data(), q.size() * sizeof(uint16_t), 0);
  markMeshopt(b, view, MeshoptMode::Attributes, 4);
  return addAccessor(
      b, view, positive ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_SHORT,
      TINYGLTF_TYPE_SCALAR, w.size(), true);
}

Status addAnimation(GltfBuild& b, const AnimationClip& clip, int mesh_node, bool quantize) {
  tinygltf::Animation anim;
  anim.name = clip.name;
  const std::vector<float> times(clip.times.begin(), clip.times.end());
  const int input = addFloats(b, times, TINYGLTF_TYPE_SCALAR, 0, true);
  for (size_t k = 0; k < clip.rotations.size(); ++k) {
    std::vector<float> xyzw;
    for (const Eigen::Quaterniond& q : clip.rotations[k]) {
      const double n = q.norm();
      if (!(n > 0) || !std::isfinite(n))
        return makeError("glTF writer: animation '" + clip.name + "': joint " + std::to_string(k) +
                         " has a zero or non-finite rotation");
      xyzw.insert(xyzw.end(),
                  {float(q.x() / n), float(q.y() / n), float(q.z() / n), float(q.w() / n)});
    }
    addChannel(anim, input, addRotations(b, xyzw, quantize), int(k), "rotation");
  }
  if (!clip.root_translation.empty()) {
    std::vector<float> xyz;
    for (const Eigen::Vector3d& p : clip.root_translation)
      xyz.insert(xyz.end(), {float(p.x()), float(p.y()), float(p.z())});
    addChannel(anim, input, addFloats(b, xyz, TINYGLTF_TYPE_VEC3, 0, false), 0, "translation");
  }
  for (size_t k = 1; k < clip.joint_translations.size(); ++k) {  // DMPL joints, root bone
    if (clip.joint_translations[k].empty()) continue;            // at its rest offset
    std::vector<float> xyz;
    for (const Eigen::Vector3d& p : clip.joint_translations[k])
      xyz.insert(xyz.end(), {float(p.x()), float(p.y()), float(p.z())});
    addChannel(anim, input, addFloats(b, xyz, TINYGLTF_TYPE_VEC3, 0, false), int(k), "translation");
  }
  if (clip.morph_weights.size() > 0) {  // T x 0 without morph targets: no channel
    const std::vector<float> w = rowMajor(clip.morph_weights);
    addChannel(anim, input, addMorphWeights(b, w, quantize), mesh_node, "weights");
  }
  b.model.animations.push_back(anim);
  return Status::success();
}

Status buildModel(const Asset& asset, const WriterOptions& options, GltfBuild& b,
                  MeshoptJson* meshopt) {
  Status st = validateAsset(asset);  // the same rules for every writer (exporter/validate_asset.h)
  if (!st) return st;

  tinygltf::Model& model = b.model;
  b.bin.reserve(estimatedBufferBytes(asset));
  b.meshopt = options.meshopt;
  model.asset.version = "2.0";
  const std::string version = asset.metadata.exporter_version.empty()
                                  ? SMPL_EXPORT_VERSION
                                  : asset.metadata.exporter_version;
  model.asset.generator = "smpl-export " + version;
  model.asset.extras = tinygltf::Value(
      tinygltf::Value::Object{{"smpl", tinygltf::Value(placeholderText(kMetadataPlaceholder))}});

  addNodesAndSkin(b, asset);
  st = addMesh(b, asset, options);
  for (const AnimationClip& clip : asset.animations)
    if (st)
      st = addAnimation(b, clip, int(asset.skeleton.names.size()), options.quantize_animation);
  if (!st) return st;
  if (b.meshopt) requireExtension(model, "EXT_meshopt_compression");
  Result<MeshoptJson> compressed = compressMeshoptViews(b);
  if (!compressed) return compressed.error();
  *meshopt = std::move(*compressed);
  b.bin.resize(align4(b.bin.size()), '\0');
  if (b.bin.size() > kMaxBufferBytes)
    return makeError("glTF writer: buffer of " + std::to_string(b.bin.size()) +
                     " bytes exceeds the GLB limit of 4 GiB");
  // The bytes stay in b.bin; tinygltf writes this buffer's JSON with a length
  // of 0 and a placeholder name, replaced by the real length afterwards.
  model.buffers.resize(1);
  model.buffers[0].name = placeholderText(kBufferPlaceholder);
  return Status::success();
}

// Replaces `placeholder` (which must occur exactly once) by `text`.
Status splice(std::string& json, const std::string& placeholder, const std::string& text) {
  const size_t at = json.find(placeholder);
  if (at == std::string::npos || json.find(placeholder, at + 1) != std::string::npos)
    return makeError("glTF writer: a name in the asset collides with a placeholder");
  json.replace(at, placeholder.size(), text);
  return Status::success();
}

Status spliceMetadata(std::string& json, const std::string& metadata) {
  Status st = splice(json, kMetadataPlaceholder, metadata);
  if (st) st = splice(json, kScenePlaceholder, metadata);
  return st;
}

void putU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFF));
}

uint32_t getU32(const std::string& in, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(in[at + size_t(i)])) << (8 * i);
  return v;
}

// The JSON chunk of tinygltf's GLB (whose buffer is empty).
Result<std::string> jsonChunk(const std::string& glb) {
  if (glb.size() < 20 || glb.compare(0, 4, "glTF") != 0 || getU32(glb, 16) != 0x4E4F534Au ||
      20 + size_t(getU32(glb, 12)) > glb.size())
    return makeError("glTF writer: tinygltf produced an unexpected GLB layout");
  return glb.substr(20, getU32(glb, 12));
}

// GLB: header, JSON chunk (space-padded), BIN chunk written once from b.bin.
std::string assembleGlb(std::string json, const std::string& bin) {
  json.resize(align4(json.size()), ' ');
  std::string out;
  out.reserve(28 + json.size() + bin.size());
  out += "glTF";
  putU32(out, 2);
  putU32(out, uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  putU32(out, uint32_t(json.size()));
  putU32(out, 0x4E4F534Au);
  out += json;
  if (!bin.empty()) {
    putU32(out, uint32_t(bin.size()));
    putU32(out, 0x004E4942u);
    out += bin;
  }
  return out;
}

Result<std::string> serializeJson(tinygltf::Model& model, bool binary) {
  std::ostringstream stream;
  try {
    tinygltf::TinyGLTF gltf;
    // .gltf is for reading: indent it; GLB stays compact.
    if (!gltf.WriteGltfSceneToStream(&model, stream, !binary, binary))
      return makeError("glTF writer: tinygltf failed to serialise the model");
  } catch (const std::exception& e) {
    return makeError(std::string("glTF writer: cannot serialise: ") + e.what());
  }
  if (binary) return jsonChunk(stream.str());
  return stream.str();
}

// RFC 3986 percent-encoding of a file name for a glTF "uri".
std::string uriEscape(const std::string& name) {
  static const char hex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~')
      out += static_cast<char>(c);
    else
      out += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

// A pretty-printed .gltf whose (empty, placeholder-named) buffer becomes the
// external file `uri` of `size` bytes: tinygltf's stream writer can only
// embed, so its buffer entry is rewritten in place.
Status pointBufferAt(std::string& json, const std::string& uri, size_t size) {
  const std::string data_uri = "\"uri\": \"data:application/octet-stream;base64,\"";
  const size_t name = json.find(kBufferPlaceholder);
  const size_t length = name == std::string::npos ? name : json.rfind("\"byteLength\": 0,", name);
  const size_t data = name == std::string::npos ? name : json.find(data_uri, name);
  if (length == std::string::npos || data == std::string::npos)
    return makeError("glTF writer: the buffer entry was not found in the serialised JSON");
  json.replace(data, data_uri.size(), "\"uri\": \"" + uriEscape(uri) + "\"");
  json.replace(name, std::strlen(kBufferPlaceholder), "\"" + uriEscape(uri) + "\"");
  json.replace(length, std::strlen("\"byteLength\": 0,"),
               "\"byteLength\": " + std::to_string(size) + ",");
  return Status();
}

class GltfWriter : public Writer {
 public:
  const char* name() const override { return "glTF"; }

  Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const override {
    WriterOptions embedded = options;
    embedded.buffer_uri.clear();
    Result<Files> files = serializeFiles(asset, embedded);
    if (!files) return files.error();
    return std::move(files->bytes);
  }

  Result<Files> serializeFiles(const Asset& asset, const WriterOptions& options) const override {
    GltfBuild b;
    MeshoptJson meshopt;
    Status st = buildModel(asset, options, b, &meshopt);
    if (!st) return st.error();
    const std::string byte_length = "\"byteLength\":" + std::to_string(b.bin.size());
    const bool external = !options.binary && !options.buffer_uri.empty();
    if (!options.binary &&
        !external) {  // .gltf, one file: tinygltf embeds the buffer as a data URI
      b.model.buffers[0].name.clear();
      b.model.buffers[0].data.assign(b.bin.begin(), b.bin.end());
      std::string().swap(b.bin);
    }
    Result<std::string> json = serializeJson(b.model, options.binary);
    if (!json) return json.error();
    st = spliceMeshoptJson(*json, meshopt, !options.binary);
    if (st) st = spliceMetadata(*json, metadataJson(asset));
    if (st && options.binary)
      st = splice(*json, "\"byteLength\":0,\"name\":" + std::string(kBufferPlaceholder),
                  byte_length);
    if (st && external) st = pointBufferAt(json.value(), options.buffer_uri, b.bin.size());
    if (!st) return st.error();
    if (options.binary) return Files{assembleGlb(std::move(*json), b.bin), std::string()};
    return Files{std::move(*json), external ? std::move(b.bin) : std::string()};
  }
};

}  // namespace

const Writer& gltfWriter() {
  static const GltfWriter writer;
  return writer;
}

}  // namespace smpl
