#include "tools/morph_error.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>

#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "writers/gltf/gltf_buffer.h"
#include "writers/gltf/gltf_draco.h"

namespace smpl {
namespace {

// Component `c` of element `i` of a VEC3 view as a float (normalised ints per
// KHR_mesh_quantization: f = max(c / 32767, -1) for SHORT, c / 127 for BYTE).
float readComponent(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t s;
      std::memcpy(&s, p, 2);
      return normalized ? std::max(float(s) / 32767.f, -1.f) : float(s);
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const int8_t s = int8_t(*p);
      return normalized ? std::max(float(s) / 127.f, -1.f) : float(s);
    }
    default:
      return 0.f;
  }
}

// `count` VEC3 elements of `view` at `offset` into rows of `out` (or at rows
// `rows` when given: the sparse values).
Status readVec3(const tinygltf::Model& m, int view, size_t offset, int type, bool normalized,
                size_t count, const std::vector<uint32_t>* rows, Eigen::MatrixXf* out) {
  if (view < 0 || size_t(view) >= m.bufferViews.size()) return makeError("glTF: bad bufferView");
  const tinygltf::BufferView& bv = m.bufferViews[size_t(view)];
  if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size()) return makeError("glTF: bad buffer");
  const std::vector<unsigned char>& data = m.buffers[size_t(bv.buffer)].data;
  const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(type)));
  const size_t stride = bv.byteStride ? bv.byteStride : 3 * size;
  const size_t begin = bv.byteOffset + offset;
  if (count > 0 && (begin + stride * (count - 1) + 3 * size > bv.byteOffset + bv.byteLength ||
                    bv.byteOffset + bv.byteLength > data.size()))
    return makeError("glTF: accessor runs past its bufferView");
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Index r = Eigen::Index(rows ? (*rows)[i] : i);
    if (r >= out->rows()) return makeError("glTF: sparse index out of range");
    for (int c = 0; c < 3; ++c)
      (*out)(r, c) = readComponent(&data[begin + i * stride + size_t(c) * size], type, normalized);
  }
  return Status::success();
}

Result<std::vector<uint32_t>> readIndices(const tinygltf::Model& m, const tinygltf::Accessor& a) {
  const auto& sp = a.sparse.indices;
  if (sp.bufferView < 0 || size_t(sp.bufferView) >= m.bufferViews.size())
    return makeError("glTF: bad sparse indices");
  const tinygltf::BufferView& bv = m.bufferViews[size_t(sp.bufferView)];
  const std::vector<unsigned char>& data = m.buffers.at(size_t(bv.buffer)).data;
  const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(sp.componentType)));
  const size_t begin = bv.byteOffset + size_t(sp.byteOffset);
  if (begin + size * size_t(a.sparse.count) > std::min(data.size(), bv.byteOffset + bv.byteLength))
    return makeError("glTF: sparse indices run past their bufferView");
  std::vector<uint32_t> out(size_t(a.sparse.count));
  for (size_t i = 0; i < out.size(); ++i) {
    uint32_t v = 0;
    std::memcpy(&v, &data[begin + i * size], size);  // little-endian hosts
    out[i] = v;
  }
  return out;
}

Result<Eigen::MatrixXf> readAccessor(const tinygltf::Model& m, int index) {
  if (index < 0 || size_t(index) >= m.accessors.size()) return makeError("glTF: bad accessor");
  const tinygltf::Accessor& a = m.accessors[size_t(index)];
  if (a.type != TINYGLTF_TYPE_VEC3) return makeError("glTF: expected a VEC3 accessor");
  Eigen::MatrixXf out = Eigen::MatrixXf::Zero(Eigen::Index(a.count), 3);
  Status st;
  if (a.bufferView >= 0)
    st = readVec3(m, a.bufferView, a.byteOffset, a.componentType, a.normalized, a.count, nullptr,
                  &out);
  if (st && a.sparse.isSparse) {
    Result<std::vector<uint32_t>> rows = readIndices(m, a);
    if (!rows) return rows.error();
    st = readVec3(m, a.sparse.values.bufferView, size_t(a.sparse.values.byteOffset),
                  a.componentType, a.normalized, rows->size(), &*rows, &out);
  }
  if (!st) return st.error();
  return out;
}

Result<Eigen::MatrixXf> dracoPositions(const tinygltf::Model& m, const tinygltf::Value& ext,
                                       size_t vertices) {
  const int view = ext.Get("bufferView").GetNumberAsInt();
  if (view < 0 || size_t(view) >= m.bufferViews.size()) return makeError("Draco: bad bufferView");
  const tinygltf::BufferView& bv = m.bufferViews[size_t(view)];
  const std::vector<unsigned char>& data = m.buffers.at(size_t(bv.buffer)).data;
  if (bv.byteOffset + bv.byteLength > data.size()) return makeError("Draco: view past buffer");
  std::map<std::string, int> ids;
  const tinygltf::Value& attributes = ext.Get("attributes");
  for (const std::string& key : attributes.Keys()) ids[key] = attributes.Get(key).GetNumberAsInt();
  Result<MeshStreams> mesh =
      decodeDraco(std::string(reinterpret_cast<const char*>(&data[bv.byteOffset]), bv.byteLength),
                  ids, vertices);
  if (!mesh) return mesh.error();
  Eigen::MatrixXf out(Eigen::Index(vertices), 3);
  for (size_t v = 0; v < vertices; ++v)
    for (int c = 0; c < 3; ++c) out(Eigen::Index(v), c) = mesh->positions[3 * v + size_t(c)];
  return out;
}

std::vector<CorrectiveLayout> correctivesOf(const tinygltf::Value& extras) {
  std::vector<CorrectiveLayout> out;
  const tinygltf::Value& list = extras.Get("smpl").Get("correctives");
  for (size_t i = 0; list.IsArray() && i < list.ArrayLen(); ++i) {
    const tinygltf::Value& e = list.Get(int(i));
    CorrectiveLayout c;
    c.feature = e.Get("feature").GetNumberAsInt();
    c.target = e.Get("target").IsString() ? e.Get("target").Get<std::string>() : "";
    c.scale = e.Get("scale").GetNumberAsDouble();
    c.offset = e.Get("offset").GetNumberAsDouble();
    c.rectified = e.Get("rectified").IsBool() && e.Get("rectified").Get<bool>();
    out.push_back(c);
  }
  return out;
}

uint32_t u32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(s[at + size_t(i)])) << (8 * i);
  return v;
}

// tinygltf (built without Draco) rejects the bufferView-less accessors of a
// Draco primitive: point them at the Draco view, which is never read as such.
std::string loadableGlb(const std::string& glb) {
  if (glb.size() < 20 || glb.find("KHR_draco_mesh_compression") == std::string::npos) return glb;
  const size_t len = u32(glb, 12);
  if (20 + len > glb.size()) return glb;
  nlohmann::json j = nlohmann::json::parse(glb.substr(20, len), nullptr, false);
  if (j.is_discarded() || !j.contains("meshes") || !j.contains("accessors")) return glb;
  int view = -1;
  for (const auto& mesh : j["meshes"])
    for (const auto& prim : mesh["primitives"])
      if (prim.contains("extensions") && prim["extensions"].contains("KHR_draco_mesh_compression"))
        view = prim["extensions"]["KHR_draco_mesh_compression"].value("bufferView", -1);
  for (auto& a : j["accessors"])
    if (!a.contains("bufferView") && !a.contains("sparse") && view >= 0) a["bufferView"] = view;
  std::string json = j.dump();
  json.resize(align4(json.size()), ' ');
  const std::string bin = glb.substr(20 + len);
  std::string out = glb.substr(0, 8);
  for (uint32_t v : {uint32_t(20 + json.size() + bin.size()), uint32_t(json.size()), 0x4E4F534Au})
    for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFF));
  out += json + bin;
  return out;
}

}  // namespace

Result<DecodedMorphs> decodeMorphs(const std::string& raw) {
  const std::string bytes = loadableGlb(raw);
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const bool glb = bytes.compare(0, 4, "glTF") == 0;
  const bool ok =
      glb ? loader.LoadBinaryFromMemory(&m, &err, &warn, p, unsigned(bytes.size()))
          : loader.LoadASCIIFromString(&m, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
  if (!ok) return makeError("glTF: cannot load: " + err);
  if (m.meshes.empty() || m.meshes[0].primitives.empty()) return makeError("glTF: no mesh");
  const tinygltf::Mesh& mesh = m.meshes[0];
  const tinygltf::Primitive& prim = mesh.primitives[0];
  DecodedMorphs out;
  auto draco = prim.extensions.find("KHR_draco_mesh_compression");
  const int pos = prim.attributes.count("POSITION") ? prim.attributes.at("POSITION") : -1;
  if (pos < 0 || size_t(pos) >= m.accessors.size()) return makeError("glTF: no POSITION");
  Result<Eigen::MatrixXf> base =
      draco != prim.extensions.end()
          ? dracoPositions(m, draco->second, m.accessors[size_t(pos)].count)
          : readAccessor(m, pos);
  if (!base) return base.error();
  out.positions = std::move(*base);
  for (const auto& target : prim.targets) {
    auto it = target.find("POSITION");
    if (it == target.end()) return makeError("glTF: morph target without POSITION");
    Result<Eigen::MatrixXf> d = readAccessor(m, it->second);
    if (!d) return d.error();
    if (d->rows() != out.positions.rows()) return makeError("glTF: morph target count mismatch");
    out.deltas.push_back(std::move(*d));
  }
  const tinygltf::Value& names = mesh.extras.Get("targetNames");
  for (size_t i = 0; i < out.deltas.size(); ++i) {
    const bool named = names.IsArray() && i < names.ArrayLen() && names.Get(int(i)).IsString();
    out.names.push_back(named ? names.Get(int(i)).Get<std::string>() : "");
    out.rest_weights.push_back(i < mesh.weights.size() ? mesh.weights[i] : 0.0);
  }
  out.correctives = correctivesOf(m.asset.extras);
  return out;
}

namespace {

// T x P weights: w_n(f_p) per target n and pose p.
Eigen::MatrixXd weightsOverPoses(const std::vector<std::string>& names,
                                 const std::vector<double>& rest,
                                 const std::vector<CorrectiveLayout>& correctives,
                                 const std::vector<Eigen::VectorXd>& features) {
  Eigen::MatrixXd w(Eigen::Index(names.size()), Eigen::Index(features.size()));
  std::map<std::string, const CorrectiveLayout*> by_name;
  for (const CorrectiveLayout& c : correctives) by_name[c.target] = &c;
  for (size_t n = 0; n < names.size(); ++n)
    for (size_t p = 0; p < features.size(); ++p) {
      auto it = by_name.find(names[n]);
      const CorrectiveLayout* c = it == by_name.end() ? nullptr : it->second;
      const bool valid = c && c->feature >= 0 && c->feature < features[p].size();
      const double mapped = valid ? c->scale * features[p][c->feature] + c->offset : rest[n];
      w(Eigen::Index(n), Eigen::Index(p)) = valid && c->rectified ? std::max(0.0, mapped) : mapped;
    }
  return w;
}

// 3V x T stack of the targets' deltas, in double.
template <class Deltas>
Eigen::MatrixXd stack(const std::vector<const Deltas*>& deltas, Eigen::Index v) {
  Eigen::MatrixXd out(3 * v, Eigen::Index(deltas.size()));
  for (size_t n = 0; n < deltas.size(); ++n)
    for (int c = 0; c < 3; ++c)
      out.col(Eigen::Index(n)).segment(c * v, v) = deltas[n]->col(c).template cast<double>();
  return out;
}

}  // namespace

Result<double> morphError(const DecodedMorphs& file, const Asset& exact, int num_poses,
                          uint64_t seed) {
  const SkinnedMesh& m = exact.mesh;
  const Eigen::Index v = m.positions.rows();
  if (file.positions.rows() != v || file.deltas.size() != m.morph_targets.size())
    return makeError("morph error: the file's mesh does not match the asset");
  std::vector<Eigen::VectorXd> features;
  for (const Eigen::VectorXd& pose : samplePoses(int(exact.skeleton.names.size()), num_poses, seed))
    features.push_back(poseFeatures(rotationsFromAxisAngle(pose)));
  std::vector<std::string> names;
  std::vector<double> rest;
  std::vector<const MorphDeltas*> exact_d;
  std::vector<const Eigen::MatrixXf*> file_d;
  for (size_t n = 0; n < m.morph_targets.size(); ++n) {
    names.push_back(m.morph_targets[n].name);
    rest.push_back(m.morph_targets[n].rest_weight);
    exact_d.push_back(&m.morph_targets[n].deltas);
    file_d.push_back(&file.deltas[n]);
  }
  const Eigen::MatrixXd w_exact =
      weightsOverPoses(names, rest, exact.metadata.correctives, features);
  const Eigen::MatrixXd w_file =
      weightsOverPoses(file.names.size() == names.size() ? file.names : names, file.rest_weights,
                       file.correctives, features);
  Eigen::MatrixXd diff = stack(file_d, v) * w_file - stack(exact_d, v) * w_exact;  // 3V x P
  Eigen::VectorXd base(3 * v);
  for (int c = 0; c < 3; ++c)
    base.segment(c * v, v) = (file.positions.col(c) - m.positions.col(c)).cast<double>();
  diff.colwise() += base;
  double worst = 0.0;
  for (Eigen::Index p = 0; p < diff.cols(); ++p)
    for (Eigen::Index i = 0; i < v; ++i) {
      const double e = std::sqrt(diff(i, p) * diff(i, p) + diff(v + i, p) * diff(v + i, p) +
                                 diff(2 * v + i, p) * diff(2 * v + i, p));
      worst = std::max(worst, e);
    }
  return worst;
}

}  // namespace smpl
