// glTF 2.0 / GLB writer. Translates an Asset into a tinygltf::Model (one
// buffer, one 4-byte aligned bufferView per accessor) and lets tinygltf write
// the JSON and the GLB container. Computes nothing about the body: it only
// converts layouts (row-major floats, glTF's v = 1 - v, 4-slot skin sets) and
// tidies float rounding so the Khronos validator reports no warnings.
#include "plugins/gltf/gltf_writer.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <sstream>

#include "exporter/metadata_json.h"

namespace smpl {
namespace {

// tinygltf 2.7 turns empty arrays inside extras into null and sorts object
// keys, so asset.extras.smpl holds this placeholder string while tinygltf
// writes, and the metadata text replaces it verbatim afterwards.
const char kMetadataPlaceholder[] = "\"smpl-export:metadata:7c1e5a90\"";

constexpr size_t kMaxBufferBytes = 0xF0000000u;  // GLB lengths are uint32

size_t align4(size_t n) { return (n + 3) & ~size_t(3); }

// Appends raw bytes as a new bufferView starting on a 4-byte boundary.
int addView(tinygltf::Model& model, const void* data, size_t size, int target) {
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  bytes.resize(align4(bytes.size()), 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();
  view.byteLength = size;
  view.target = target;
  const unsigned char* begin = static_cast<const unsigned char*>(data);
  bytes.insert(bytes.end(), begin, begin + size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

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
int addFloats(tinygltf::Model& model, const std::vector<float>& values, int type, int target,
              bool bounds) {
  const int n = componentCount(type);
  tinygltf::Accessor accessor;
  accessor.bufferView = addView(model, values.data(), values.size() * sizeof(float), target);
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = type;
  accessor.count = values.size() / size_t(n);
  if (bounds && !values.empty()) {
    accessor.minValues.assign(values.begin(), values.begin() + n);
    accessor.maxValues = accessor.minValues;
    for (size_t i = 0; i < values.size(); ++i) {
      double v = values[i];
      accessor.minValues[i % n] = std::min(accessor.minValues[i % n], v);
      accessor.maxValues[i % n] = std::max(accessor.maxValues[i % n], v);
    }
  }
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

template <class T>
int addIntegers(tinygltf::Model& model, const std::vector<T>& values, int component_type, int type,
                int target) {
  tinygltf::Accessor accessor;
  accessor.bufferView = addView(model, values.data(), values.size() * sizeof(T), target);
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = values.size() / size_t(componentCount(type));
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

// JOINTS_n in the narrowest type that holds every joint index.
int addJoints(tinygltf::Model& model, const std::vector<uint16_t>& joints, int num_joints) {
  if (num_joints < 256) {
    std::vector<uint8_t> narrow(joints.begin(), joints.end());
    return addIntegers(model, narrow, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4,
                       TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  return addIntegers(model, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4,
                     TINYGLTF_TARGET_ARRAY_BUFFER);
}

std::string shapeOf(Eigen::Index rows, Eigen::Index cols) {
  return "(" + std::to_string(rows) + "," + std::to_string(cols) + ")";
}

Status expectShape(const char* what, Eigen::Index rows, Eigen::Index cols, Eigen::Index want_rows,
                   Eigen::Index want_cols) {
  if (rows == want_rows && cols == want_cols) return Status::success();
  return makeError(std::string("glTF writer: ") + what + " has shape " + shapeOf(rows, cols) +
                   "; expected " + shapeOf(want_rows, want_cols));
}

Status checkSkeleton(const Skeleton& s) {
  const Eigen::Index k = Eigen::Index(s.names.size());
  if (k == 0) return makeError("glTF writer: skeleton has no joints");
  if (Eigen::Index(s.parents.size()) != k)
    return makeError("glTF writer: skeleton has " + std::to_string(k) + " names but " +
                     std::to_string(s.parents.size()) + " parents");
  Status st = expectShape("skeleton.rest_local", s.rest_local.rows(), s.rest_local.cols(), k, 3);
  if (!st) return st;
  st = expectShape("skeleton.rest_world", s.rest_world.rows(), s.rest_world.cols(), k, 3);
  if (!st) return st;
  if (s.parents[0] != -1) return makeError("glTF writer: joint 0 must be the root (parent -1)");
  for (Eigen::Index j = 1; j < k; ++j) {
    // p(k) < k rules out loops and leaves joint 0 the only root (one skin root).
    if (s.parents[j] < 0 || s.parents[j] >= j)
      return makeError("glTF writer: joint " + std::to_string(j) + " ('" + s.names[j] +
                       "') has parent " + std::to_string(s.parents[j]) + "; expected 0.." +
                       std::to_string(j - 1));
  }
  if (!s.rest_local.allFinite() || !s.rest_world.allFinite())
    return makeError("glTF writer: skeleton rest positions are not finite");
  return Status::success();
}

Status checkMesh(const SkinnedMesh& m) {
  const Eigen::Index v = m.positions.rows();
  if (v == 0) return makeError("glTF writer: mesh has no vertices");
  Status st = expectShape("mesh.positions", v, m.positions.cols(), v, 3);
  if (st) st = expectShape("mesh.normals", m.normals.rows(), m.normals.cols(), v, 3);
  if (st && m.uvs.rows() != 0) st = expectShape("mesh.uvs", m.uvs.rows(), m.uvs.cols(), v, 2);
  if (st)
    st = expectShape("mesh.triangles", m.triangles.rows(), m.triangles.cols(), m.triangles.rows(),
                     3);
  if (st && m.joints.cols() == 0) st = makeError("glTF writer: mesh has no skin influences");
  if (st) st = expectShape("mesh.joints", m.joints.rows(), m.joints.cols(), v, m.joints.cols());
  if (st) st = expectShape("mesh.weights", m.weights.rows(), m.weights.cols(), v, m.joints.cols());
  if (!st) return st;
  if (m.triangles.rows() == 0) return makeError("glTF writer: mesh has no triangles");
  if (m.triangles.minCoeff() < 0 || m.triangles.maxCoeff() >= v)
    return makeError("glTF writer: mesh.triangles index out of range 0.." + std::to_string(v - 1));
  if (!m.positions.allFinite() || !m.normals.allFinite() || !m.uvs.allFinite())
    return makeError("glTF writer: mesh positions, normals or uvs are not finite");
  for (const MorphTarget& t : m.morph_targets) {
    st = expectShape(("morph target '" + t.name + "'").c_str(), t.deltas.rows(), t.deltas.cols(), v,
                     3);
    if (!st) return st;
    if (!t.deltas.allFinite())
      return makeError("glTF writer: morph target '" + t.name + "' has non-finite deltas");
  }
  return Status::success();
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

// JOINTS_n / WEIGHTS_n attributes, ceil(M/4) sets.
Status addSkinAttributes(tinygltf::Model& model, tinygltf::Primitive& prim, const SkinnedMesh& m,
                         int num_joints) {
  const int sets = int((m.joints.cols() + 3) / 4);
  const size_t v_count = size_t(m.positions.rows());
  std::vector<std::vector<uint16_t>> joints(size_t(sets), std::vector<uint16_t>(4 * v_count));
  std::vector<std::vector<float>> weights(size_t(sets), std::vector<float>(4 * v_count));
  std::vector<uint16_t> vj;
  std::vector<float> vw;
  for (size_t v = 0; v < v_count; ++v) {
    Status st = packVertexSkin(m, Eigen::Index(v), num_joints, sets, vj, vw);
    if (!st) return st;
    for (int s = 0; s < sets; ++s)
      for (int c = 0; c < 4; ++c) {
        joints[size_t(s)][4 * v + size_t(c)] = vj[size_t(4 * s + c)];
        weights[size_t(s)][4 * v + size_t(c)] = vw[size_t(4 * s + c)];
      }
  }
  for (int s = 0; s < sets; ++s) {
    prim.attributes["JOINTS_" + std::to_string(s)] =
        addJoints(model, joints[size_t(s)], num_joints);
    prim.attributes["WEIGHTS_" + std::to_string(s)] = addFloats(
        model, weights[size_t(s)], TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
  }
  return Status::success();
}

int addIndices(tinygltf::Model& model, const Eigen::MatrixXi& triangles, Eigen::Index v_count) {
  std::vector<uint32_t> indices;
  indices.reserve(size_t(triangles.size()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c) indices.push_back(uint32_t(triangles(f, c)));
  // 65535 is the primitive restart value of UNSIGNED_SHORT, so it must not occur.
  if (v_count < 65535) {
    std::vector<uint16_t> narrow(indices.begin(), indices.end());
    return addIntegers(model, narrow, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                       TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
  return addIntegers(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
}

Status addMesh(tinygltf::Model& model, const Asset& asset) {
  const SkinnedMesh& m = asset.mesh;
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.attributes["POSITION"] = addFloats(model, rowMajor(m.positions), TINYGLTF_TYPE_VEC3,
                                          TINYGLTF_TARGET_ARRAY_BUFFER, true);
  prim.attributes["NORMAL"] = addFloats(model, unitNormals(m.normals), TINYGLTF_TYPE_VEC3,
                                        TINYGLTF_TARGET_ARRAY_BUFFER, false);
  if (m.uvs.rows() > 0)
    prim.attributes["TEXCOORD_0"] = addFloats(model, flippedUvs(m.uvs), TINYGLTF_TYPE_VEC2,
                                              TINYGLTF_TARGET_ARRAY_BUFFER, false);
  Status st = addSkinAttributes(model, prim, m, int(asset.skeleton.names.size()));
  if (!st) return st;
  prim.indices = addIndices(model, m.triangles, m.positions.rows());

  tinygltf::Mesh mesh;
  mesh.name = asset.name;
  tinygltf::Value::Array names;
  for (const MorphTarget& t : m.morph_targets) {
    int accessor = addFloats(model, rowMajor(t.deltas), TINYGLTF_TYPE_VEC3,
                             TINYGLTF_TARGET_ARRAY_BUFFER, true);
    prim.targets.push_back({{"POSITION", accessor}});
    mesh.weights.push_back(t.rest_weight);  // non-zero only for the unit corrective encoding
    names.emplace_back(t.name);
  }
  // An empty targetNames would serialise as null (tinygltf), so omit it.
  if (!names.empty())
    mesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(names)}});
  mesh.primitives.push_back(prim);
  model.meshes.push_back(mesh);
  return Status::success();
}

// Joint nodes 0..K-1 in model order, then the mesh node K (a scene root, as
// the validator requires of skinned meshes), then the skin.
void addNodesAndSkin(tinygltf::Model& model, const Asset& asset) {
  const Skeleton& s = asset.skeleton;
  const int k_count = int(s.names.size());
  for (int k = 0; k < k_count; ++k) {
    tinygltf::Node node;
    node.name = s.names[size_t(k)];
    node.translation = {s.rest_local(k, 0), s.rest_local(k, 1), s.rest_local(k, 2)};
    model.nodes.push_back(node);
  }
  for (int k = 1; k < k_count; ++k) model.nodes[size_t(s.parents[size_t(k)])].children.push_back(k);

  tinygltf::Node mesh_node;
  mesh_node.name = asset.name;
  mesh_node.mesh = 0;
  mesh_node.skin = 0;
  model.nodes.push_back(mesh_node);

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
  skin.inverseBindMatrices = addFloats(model, ibm, TINYGLTF_TYPE_MAT4, 0, false);
  model.skins.push_back(skin);

  tinygltf::Scene scene;
  scene.name = asset.name;
  scene.nodes = {0, k_count};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
}

Status checkClip(const AnimationClip& clip, const Asset& asset) {
  const std::string where = "glTF writer: animation '" + clip.name + "': ";
  const size_t t_count = clip.times.size();
  if (t_count == 0) return makeError(where + "no frames");
  for (size_t t = 0; t < t_count; ++t) {
    // Checked in float: that is what the file stores and the validator reads.
    float now = float(clip.times[t]);
    if (!std::isfinite(clip.times[t]) || now < 0 || (t > 0 && !(now > float(clip.times[t - 1]))))
      return makeError(where + "frame times must be finite, >= 0 and strictly increasing (frame " +
                       std::to_string(t) + ")");
  }
  if (!clip.rotations.empty() && clip.rotations.size() != asset.skeleton.names.size())
    return makeError(where + "rotations for " + std::to_string(clip.rotations.size()) +
                     " joints; the skeleton has " + std::to_string(asset.skeleton.names.size()));
  for (const auto& track : clip.rotations)
    if (track.size() != t_count) return makeError(where + "a rotation track's length is not T");
  if (!clip.root_translation.empty() && clip.root_translation.size() != t_count)
    return makeError(where + "root_translation length is not T");
  const Eigen::Index targets = Eigen::Index(asset.mesh.morph_targets.size());
  if (clip.morph_weights.rows() != 0) {
    Status st = expectShape(("animation '" + clip.name + "' morph_weights").c_str(),
                            clip.morph_weights.rows(), clip.morph_weights.cols(),
                            Eigen::Index(t_count), targets);
    if (!st) return st;
    if (targets == 0 || !clip.morph_weights.allFinite())
      return makeError(where + "morph_weights need morph targets and finite values");
  }
  if (clip.rotations.empty() && clip.root_translation.empty() && clip.morph_weights.rows() == 0)
    return makeError(where + "no channels");
  return Status::success();
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

Status addAnimation(tinygltf::Model& model, const AnimationClip& clip, int mesh_node) {
  tinygltf::Animation anim;
  anim.name = clip.name;
  const std::vector<float> times(clip.times.begin(), clip.times.end());
  const int input = addFloats(model, times, TINYGLTF_TYPE_SCALAR, 0, true);
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
    addChannel(anim, input, addFloats(model, xyzw, TINYGLTF_TYPE_VEC4, 0, false), int(k),
               "rotation");
  }
  if (!clip.root_translation.empty()) {
    std::vector<float> xyz;
    for (const Eigen::Vector3d& p : clip.root_translation)
      xyz.insert(xyz.end(), {float(p.x()), float(p.y()), float(p.z())});
    addChannel(anim, input, addFloats(model, xyz, TINYGLTF_TYPE_VEC3, 0, false), 0, "translation");
  }
  if (clip.morph_weights.rows() > 0)
    addChannel(anim, input,
               addFloats(model, rowMajor(clip.morph_weights), TINYGLTF_TYPE_SCALAR, 0, false),
               mesh_node, "weights");
  model.animations.push_back(anim);
  return Status::success();
}

Result<tinygltf::Model> buildModel(const Asset& asset) {
  Status st = checkSkeleton(asset.skeleton);
  if (st) st = checkMesh(asset.mesh);
  for (const AnimationClip& clip : asset.animations)
    if (st) st = checkClip(clip, asset);
  if (!st) return st.error();

  tinygltf::Model model;
  model.buffers.resize(1);
  model.asset.version = "2.0";
  const std::string version = asset.metadata.exporter_version.empty()
                                  ? SMPL_EXPORT_VERSION
                                  : asset.metadata.exporter_version;
  model.asset.generator = "smpl-export " + version;
  const std::string placeholder(kMetadataPlaceholder + 1, sizeof(kMetadataPlaceholder) - 3);
  model.asset.extras =
      tinygltf::Value(tinygltf::Value::Object{{"smpl", tinygltf::Value(placeholder)}});

  addNodesAndSkin(model, asset);
  st = addMesh(model, asset);
  for (const AnimationClip& clip : asset.animations)
    if (st) st = addAnimation(model, clip, int(asset.skeleton.names.size()));
  if (!st) return st.error();
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  bytes.resize(align4(bytes.size()), 0);
  if (bytes.size() > kMaxBufferBytes)
    return makeError("glTF writer: buffer of " + std::to_string(bytes.size()) +
                     " bytes exceeds the GLB limit of 4 GiB");
  return model;
}

// Replaces the placeholder (which must occur exactly once) by the metadata text.
Result<std::string> spliceMetadata(std::string json, const std::string& metadata) {
  const size_t at = json.find(kMetadataPlaceholder);
  const size_t len = sizeof(kMetadataPlaceholder) - 1;
  if (at == std::string::npos || json.find(kMetadataPlaceholder, at + 1) != std::string::npos)
    return makeError("glTF writer: a name in the asset collides with the metadata placeholder");
  json.replace(at, len, metadata);
  return json;
}

void putU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFF));
}

uint32_t getU32(const std::string& in, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(in[at + size_t(i)])) << (8 * i);
  return v;
}

// GLB from tinygltf: splice the JSON chunk, keep the BIN chunk byte for byte.
Result<std::string> spliceGlb(const std::string& glb, const std::string& metadata) {
  if (glb.size() < 20 || glb.compare(0, 4, "glTF") != 0 || getU32(glb, 16) != 0x4E4F534Au ||
      20 + size_t(getU32(glb, 12)) > glb.size())
    return makeError("glTF writer: tinygltf produced an unexpected GLB layout");
  const size_t json_len = getU32(glb, 12);
  Result<std::string> json = spliceMetadata(glb.substr(20, json_len), metadata);
  if (!json) return json;
  std::string chunk = std::move(*json);
  chunk.resize(align4(chunk.size()), ' ');
  const std::string bin = glb.substr(20 + json_len);
  std::string out = "glTF";
  putU32(out, 2);
  putU32(out, uint32_t(12 + 8 + chunk.size() + bin.size()));
  putU32(out, uint32_t(chunk.size()));
  putU32(out, 0x4E4F534Au);
  out += chunk;
  out += bin;
  return out;
}

class GltfWriter : public Writer {
 public:
  const char* name() const override { return "glTF"; }

  Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const override {
    Result<tinygltf::Model> model = buildModel(asset);
    if (!model) return model.error();
    std::ostringstream stream;
    try {
      tinygltf::TinyGLTF gltf;
      // .gltf is for reading: indent it; GLB stays compact.
      if (!gltf.WriteGltfSceneToStream(&*model, stream, !options.binary, options.binary))
        return makeError("glTF writer: tinygltf failed to serialise the model");
    } catch (const std::exception& e) {
      return makeError(std::string("glTF writer: cannot serialise: ") + e.what());
    }
    const std::string metadata = metadataJson(asset);
    if (options.binary) return spliceGlb(stream.str(), metadata);
    return spliceMetadata(stream.str(), metadata);
  }
};

}  // namespace

const Writer& gltfWriter() {
  static const GltfWriter writer;
  return writer;
}

}  // namespace smpl
