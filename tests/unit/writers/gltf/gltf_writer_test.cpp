// glTF writer: builds small synthetic assets in code, writes them, reads the
// bytes back with tinygltf's loader and compares against the inputs. Set
// SMPL_GLTF_OUT_DIR to also keep the written files, e.g. for
// `node tests/validator/validate.js DIR/*`.
#include "writers/gltf/gltf_writer.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>

#include "exporter/metadata_json.h"
#include "tests/unit/test_asset.h"
#include "writers/writer.h"

namespace smpl {
namespace {

using test::AssetSpec;
using test::makeAsset;

void keepOutput(const std::string& name, const std::string& bytes) {
  const char* dir = std::getenv("SMPL_GLTF_OUT_DIR");
  if (dir == nullptr) return;
  std::ofstream(std::string(dir) + "/" + name, std::ios::binary) << bytes;
}

tinygltf::Model load(const std::string& bytes, bool binary) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  bool ok = binary ? loader.LoadBinaryFromMemory(
                         &model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                         unsigned(bytes.size()))
                   : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                unsigned(bytes.size()), "");
  EXPECT_TRUE(ok) << err;
  EXPECT_EQ(warn, "");
  return model;
}

// The written file as tinygltf reads it, plus its JSON as an independent
// parser sees it (tinygltf's loader drops empty arrays from extras).
struct Loaded : tinygltf::Model {
  nlohmann::ordered_json json;
};

std::string jsonText(const std::string& bytes, bool binary) {
  if (!binary) return bytes;
  uint32_t length = 0;
  if (bytes.size() >= 20) std::memcpy(&length, bytes.data() + 12, 4);
  EXPECT_LE(20u + length, bytes.size());
  return bytes.size() >= 20 + size_t(length) ? bytes.substr(20, length) : std::string("{}");
}

Loaded writeAndLoad(const Asset& a, bool binary, const std::string& keep_as) {
  WriterOptions options;
  options.binary = binary;
  Result<std::string> bytes = gltfWriter().serialize(a, options);
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : bytes.message());
  if (!bytes.ok()) return {};
  keepOutput(keep_as, *bytes);
  Loaded loaded;
  static_cast<tinygltf::Model&>(loaded) = load(*bytes, binary);
  loaded.json = nlohmann::ordered_json::parse(jsonText(*bytes, binary), nullptr, false);
  EXPECT_FALSE(loaded.json.is_discarded());
  return loaded;
}

// Component values of an accessor as doubles, honouring offsets and type.
std::vector<double> readAccessor(const tinygltf::Model& m, int index) {
  const tinygltf::Accessor& acc = m.accessors.at(size_t(index));
  const tinygltf::BufferView& view = m.bufferViews.at(size_t(acc.bufferView));
  const unsigned char* p =
      m.buffers.at(size_t(view.buffer)).data.data() + view.byteOffset + acc.byteOffset;
  const size_t n = acc.count * size_t(tinygltf::GetNumComponentsInType(uint32_t(acc.type)));
  EXPECT_LE(view.byteOffset + acc.byteOffset +
                n * size_t(tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType))),
            m.buffers[size_t(view.buffer)].data.size());
  std::vector<double> out(n);
  for (size_t i = 0; i < n; ++i) {
    switch (acc.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p + 4 * i, 4);
        out[i] = f;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        out[i] = p[i];
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t s;
        std::memcpy(&s, p + 2 * i, 2);
        out[i] = s;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t u;
        std::memcpy(&u, p + 4 * i, 4);
        out[i] = u;
        break;
      }
      default:
        ADD_FAILURE() << "unexpected component type " << acc.componentType;
    }
  }
  return out;
}

nlohmann::json toJson(const tinygltf::Value& v) {
  switch (v.Type()) {
    case tinygltf::INT_TYPE:
      return v.Get<int>();
    case tinygltf::REAL_TYPE:
      return v.Get<double>();
    case tinygltf::BOOL_TYPE:
      return v.Get<bool>();
    case tinygltf::STRING_TYPE:
      return v.Get<std::string>();
    case tinygltf::ARRAY_TYPE: {
      nlohmann::json a = nlohmann::json::array();
      for (size_t i = 0; i < v.ArrayLen(); ++i) a.push_back(toJson(v.Get(int(i))));
      return a;
    }
    case tinygltf::OBJECT_TYPE: {
      nlohmann::json o = nlohmann::json::object();
      for (const std::string& key : v.Keys()) o[key] = toJson(v.Get(key));
      return o;
    }
    default:
      return nullptr;
  }
}

void expectSkeleton(const tinygltf::Model& m, const Asset& a) {
  const int k_count = int(a.skeleton.names.size());
  ASSERT_EQ(m.nodes.size(), size_t(k_count + 1));
  std::vector<int> parent_of(m.nodes.size(), -1);
  for (size_t n = 0; n < m.nodes.size(); ++n)
    for (int c : m.nodes[n].children) parent_of[size_t(c)] = int(n);
  for (int k = 0; k < k_count; ++k) {
    const tinygltf::Node& node = m.nodes[size_t(k)];
    EXPECT_EQ(node.name, a.skeleton.names[size_t(k)]);
    EXPECT_EQ(parent_of[size_t(k)], a.skeleton.parents[size_t(k)]);
    EXPECT_TRUE(node.rotation.empty() && node.scale.empty() && node.matrix.empty());
    ASSERT_EQ(node.translation.size(), 3u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(node.translation[size_t(c)], a.skeleton.rest_local(k, c));
  }
  const tinygltf::Node& mesh_node = m.nodes[size_t(k_count)];
  EXPECT_EQ(mesh_node.name, a.name);
  EXPECT_EQ(mesh_node.mesh, 0);
  EXPECT_EQ(mesh_node.skin, 0);
  EXPECT_EQ(parent_of[size_t(k_count)], -1);
  ASSERT_EQ(m.scenes.size(), 1u);
  EXPECT_EQ(m.scenes[0].nodes, (std::vector<int>{0, k_count}));

  ASSERT_EQ(m.skins.size(), 1u);
  std::vector<int> all(static_cast<size_t>(k_count));
  for (int k = 0; k < k_count; ++k) all[size_t(k)] = k;
  EXPECT_EQ(m.skins[0].joints, all);
  EXPECT_EQ(m.skins[0].skeleton, 0);
  std::vector<double> ibm = readAccessor(m, m.skins[0].inverseBindMatrices);
  ASSERT_EQ(ibm.size(), size_t(16 * k_count));
  for (int k = 0; k < k_count; ++k)
    for (int i = 0; i < 16; ++i) {
      const int row = i % 4, col = i / 4;  // column-major
      double want = row == col ? 1.0 : 0.0;
      if (col == 3 && row < 3) want = float(-a.skeleton.rest_world(k, row));
      EXPECT_EQ(ibm[size_t(16 * k + i)], want) << "joint " << k << " element " << i;
    }
}

const tinygltf::Primitive& onlyPrimitive(const tinygltf::Model& m) {
  static const tinygltf::Primitive none;
  EXPECT_EQ(m.meshes.size(), 1u);
  if (m.meshes.size() != 1 || m.meshes[0].primitives.size() != 1) return none;
  return m.meshes[0].primitives[0];
}

void expectVertexData(const tinygltf::Model& m, const Asset& a) {
  const tinygltf::Primitive& p = onlyPrimitive(m);
  const SkinnedMesh& mesh = a.mesh;
  EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
  ASSERT_TRUE(p.attributes.count("POSITION"));
  const tinygltf::Accessor& pos = m.accessors[size_t(p.attributes.at("POSITION"))];
  EXPECT_EQ(pos.count, size_t(mesh.positions.rows()));
  EXPECT_EQ(pos.type, TINYGLTF_TYPE_VEC3);
  const Eigen::RowVector3f lo = mesh.positions.colwise().minCoeff();
  const Eigen::RowVector3f hi = mesh.positions.colwise().maxCoeff();
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(pos.minValues.at(size_t(c)), lo(c));
    EXPECT_EQ(pos.maxValues.at(size_t(c)), hi(c));
  }
  std::vector<double> xyz = readAccessor(m, p.attributes.at("POSITION"));
  std::vector<double> nrm = readAccessor(m, p.attributes.at("NORMAL"));
  for (Eigen::Index v = 0; v < mesh.positions.rows(); ++v)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(xyz[size_t(3 * v + c)], mesh.positions(v, c));
      EXPECT_NEAR(nrm[size_t(3 * v + c)], mesh.normals(v, c), 1e-6);
    }
  EXPECT_EQ(p.attributes.count("TEXCOORD_0"), mesh.uvs.rows() > 0 ? 1u : 0u);
  if (mesh.uvs.rows() > 0) {
    std::vector<double> uv = readAccessor(m, p.attributes.at("TEXCOORD_0"));
    for (Eigen::Index v = 0; v < mesh.uvs.rows(); ++v) {
      EXPECT_EQ(uv[size_t(2 * v)], mesh.uvs(v, 0));
      EXPECT_EQ(uv[size_t(2 * v + 1)], 1.0f - mesh.uvs(v, 1));
    }
  }
  std::vector<double> idx = readAccessor(m, p.indices);
  ASSERT_EQ(idx.size(), size_t(mesh.triangles.size()));
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(idx[size_t(3 * f + c)], mesh.triangles(f, c));
}

// Dense per-vertex weights from the file equal the input's (which sum to 1).
void expectSkinWeights(const tinygltf::Model& m, const Asset& a) {
  const tinygltf::Primitive& p = onlyPrimitive(m);
  const SkinnedMesh& mesh = a.mesh;
  const int sets = int((mesh.joints.cols() + 3) / 4);
  const int k_count = int(a.skeleton.names.size());
  EXPECT_EQ(p.attributes.count("JOINTS_" + std::to_string(sets)), 0u);
  // Sparse per-vertex sums: dense V x K would be large for the wide test.
  std::vector<std::map<int, double>> got(size_t(mesh.positions.rows()));
  for (int s = 0; s < sets; ++s) {
    const std::string suffix = std::to_string(s);
    ASSERT_TRUE(p.attributes.count("JOINTS_" + suffix) && p.attributes.count("WEIGHTS_" + suffix));
    const tinygltf::Accessor& ja = m.accessors[size_t(p.attributes.at("JOINTS_" + suffix))];
    EXPECT_EQ(ja.componentType, k_count < 256 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
                                              : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    std::vector<double> j = readAccessor(m, p.attributes.at("JOINTS_" + suffix));
    std::vector<double> w = readAccessor(m, p.attributes.at("WEIGHTS_" + suffix));
    for (Eigen::Index v = 0; v < mesh.positions.rows(); ++v)
      for (int c = 0; c < 4; ++c) {
        const double weight = w[size_t(4 * v + c)];
        const int joint = int(j[size_t(4 * v + c)]);
        if (weight == 0) {
          EXPECT_EQ(joint, 0) << "zero-weight slot of vertex " << v;
        } else {
          got[size_t(v)][joint] += weight;
        }
      }
  }
  double worst = 0;
  for (Eigen::Index v = 0; v < mesh.joints.rows(); ++v) {
    std::map<int, double> want;
    for (Eigen::Index i = 0; i < mesh.joints.cols(); ++i)
      if (mesh.weights(v, i) != 0) want[mesh.joints(v, i)] += mesh.weights(v, i);
    ASSERT_EQ(got[size_t(v)].size(), want.size()) << "vertex " << v;
    for (const auto& [joint, weight] : want)
      worst = std::max(worst, std::fabs(got[size_t(v)][joint] - weight));
  }
  EXPECT_LT(worst, 1e-6);
}

void expectMorphTargets(const tinygltf::Model& m, const Asset& a) {
  const tinygltf::Primitive& p = onlyPrimitive(m);
  const auto& targets = a.mesh.morph_targets;
  ASSERT_EQ(p.targets.size(), targets.size());
  EXPECT_EQ(m.meshes[0].weights, std::vector<double>(targets.size(), 0.0));
  for (size_t t = 0; t < targets.size(); ++t) {
    const tinygltf::Accessor& acc = m.accessors[size_t(p.targets[t].at("POSITION"))];
    EXPECT_EQ(acc.minValues.size(), 3u);
    EXPECT_EQ(acc.maxValues.size(), 3u);
    std::vector<double> d = readAccessor(m, p.targets[t].at("POSITION"));
    ASSERT_EQ(d.size(), size_t(targets[t].deltas.size()));
    for (Eigen::Index v = 0; v < targets[t].deltas.rows(); ++v)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(d[size_t(3 * v + c)], targets[t].deltas(v, c));
  }
  nlohmann::json names = nlohmann::json::array();
  for (const MorphTarget& t : targets) names.push_back(t.name);
  if (targets.empty()) {
    EXPECT_FALSE(m.meshes[0].extras.Has("targetNames"));
  } else {
    EXPECT_EQ(toJson(m.meshes[0].extras.Get("targetNames")), names);
  }
}

// asset.extras.smpl equals metadataJson, key order included.
void expectMetadata(const Loaded& m, const Asset& a) {
  EXPECT_EQ(m.asset.version, "2.0");
  EXPECT_EQ(m.asset.generator, "smpl-export " + a.metadata.exporter_version);
  ASSERT_TRUE(m.json.contains("asset") && m.json["asset"].contains("extras"));
  EXPECT_EQ(m.json["asset"]["extras"]["smpl"].dump(),
            nlohmann::ordered_json::parse(metadataJson(a)).dump());
}

void expectAsset(const Loaded& m, const Asset& a) {
  expectSkeleton(m, a);
  expectVertexData(m, a);
  expectSkinWeights(m, a);
  expectMorphTargets(m, a);
  expectMetadata(m, a);
  for (const tinygltf::BufferView& view : m.bufferViews) EXPECT_EQ(view.byteOffset % 4, 0u);
  EXPECT_EQ(m.buffers.size(), 1u);
}

TEST(GltfWriter, GlbFourInfluencesWithUvs) {
  const Asset a = makeAsset({});
  expectAsset(writeAndLoad(a, true, "m4_uv.glb"), a);
}

// serializeFiles hands a GLB over as its head (header, JSON chunk, BIN chunk
// header), the BIN data apart, and the float morph targets' deltas, the
// clip's rotation and morph weight keys as splices of the asset's own arrays
// (not copied), so the CLI writes the buffer without copying it behind the
// head; in order they are serialize()'s bytes.
TEST(GltfWriter, GlbHeadAndBufferAreTheWholeFile) {
  AssetSpec spec;
  spec.frames = 7;
  const Asset a = makeAsset(spec);
  const Writer* w = writerForPath("x.glb");
  ASSERT_NE(w, nullptr);
  Result<Writer::Files> files = w->serializeFiles(a, WriterOptions());
  Result<std::string> whole = w->serialize(a, WriterOptions());
  ASSERT_TRUE(files && whole);
  std::string joined = files->bytes;
  for (const ByteSpan& part : files->tailParts())
    joined.append(static_cast<const char*>(part.data), part.size);
  EXPECT_EQ(joined, *whole);
  EXPECT_EQ(files->size(), whole->size());
  const MorphWeightTrack& track = a.animations[0].morph_weights;
  ASSERT_GT(track.size(), 0);
  const std::vector<MorphTarget>& targets = a.mesh.morph_targets;
  const std::vector<RotationTrack>& rotations = a.animations[0].rotations;
  ASSERT_GT(targets.size(), 0u);
  // In the order glTF's views have them: the targets, the rotations, the weights.
  ASSERT_EQ(files->splices.size(), targets.size() + rotations.size() + 1);
  for (size_t n = 0; n < targets.size(); ++n) {
    EXPECT_EQ(files->splices[n].bytes.data, static_cast<const void*>(targets[n].deltas.data()))
        << n;
    EXPECT_EQ(files->splices[n].bytes.size, size_t(targets[n].deltas.size()) * sizeof(float)) << n;
  }
  for (size_t k = 0; k < rotations.size(); ++k) {
    const Writer::Splice& s = files->splices[targets.size() + k];
    EXPECT_EQ(s.bytes.data, static_cast<const void*>(rotations[k].data())) << k;
    EXPECT_EQ(s.bytes.size, rotations[k].size() * 4 * sizeof(float)) << k;
  }
  EXPECT_EQ(files->splices.back().bytes.data, static_cast<const void*>(track.data()));
  EXPECT_EQ(files->splices.back().bytes.size, size_t(track.size()) * sizeof(float));
  ASSERT_GT(files->tail.size(), 0u);
  EXPECT_EQ(files->bytes.size() % 4, 0u);
  EXPECT_EQ(files->bytes.compare(files->bytes.size() - 4, 4, "BIN\0", 4), 0);
  EXPECT_TRUE(files->buffer.empty());
  // meshopt re-encodes the views from the buffer: nothing is spliced there.
  WriterOptions meshopt;
  meshopt.meshopt = true;
  if (meshoptAvailable()) {
    Result<Writer::Files> packed = w->serializeFiles(a, meshopt);
    ASSERT_TRUE(packed);
    EXPECT_TRUE(packed->splices.empty());
  }
}

TEST(GltfWriter, GlbEightInfluencesWithoutUvs) {
  AssetSpec spec;
  spec.influences = 8;
  spec.uvs = false;
  spec.vertices = 5000;  // many float sums for the validator's weight check
  const Asset a = makeAsset(spec);
  const Loaded m = writeAndLoad(a, true, "m8_nouv.glb");
  expectAsset(m, a);
  EXPECT_EQ(onlyPrimitive(m).attributes.count("JOINTS_1"), 1u);
}

TEST(GltfWriter,
     GlbAllTwentyFourInfluencesWritesSixSets) {  // --max-influences all on a 24-joint body
  AssetSpec spec;
  spec.joints = 24;
  spec.influences = 24;
  const Asset a = makeAsset(spec);
  const Loaded m = writeAndLoad(a, true, "m24.glb");
  expectAsset(m, a);
  for (int s = 0; s < 6; ++s)
    EXPECT_EQ(onlyPrimitive(m).attributes.count("WEIGHTS_" + std::to_string(s)), 1u) << s;
  EXPECT_EQ(onlyPrimitive(m).attributes.count("JOINTS_6"), 0u);
}

TEST(GltfWriter, GlbFiveInfluencesPadsSecondSet) {
  AssetSpec spec;
  spec.influences = 5;
  const Asset a = makeAsset(spec);
  expectAsset(writeAndLoad(a, true, "m5.glb"), a);
}

TEST(GltfWriter, EmbeddedGltfMatchesGlb) {
  AssetSpec spec;
  spec.frames = 4;
  const Asset a = makeAsset(spec);
  const Loaded m = writeAndLoad(a, false, "anim.gltf");
  expectAsset(m, a);
  EXPECT_EQ(m.buffers[0].uri.rfind("data:application/octet-stream;base64,", 0), 0u);
}

TEST(GltfWriter, NoMorphTargetsAndEmptyMetadataLists) {
  AssetSpec spec;
  spec.morph_targets = 0;
  Asset a = makeAsset(spec);
  a.metadata.correctives.clear();
  a.metadata.betas.clear();
  const Loaded m = writeAndLoad(a, true, "no_targets.glb");
  expectAsset(m, a);
  // tinygltf alone would write these empty lists as null.
  const nlohmann::ordered_json& smpl = m.json["asset"]["extras"]["smpl"];
  for (const char* key : {"betas", "expression", "correctives", "morph_targets"})
    EXPECT_TRUE(smpl[key].is_array() && smpl[key].empty()) << key;
}

TEST(GltfWriter, WideTypesForManyJointsAndVertices) {
  AssetSpec spec;
  spec.joints = 300;
  spec.vertices = 65536;
  spec.morph_targets = 1;
  const Asset a = makeAsset(spec);
  const Loaded m = writeAndLoad(a, true, "wide.glb");
  expectAsset(m, a);
  EXPECT_EQ(m.accessors[size_t(onlyPrimitive(m).indices)].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

TEST(GltfWriter, ShortIndicesBelowRestartValue) {
  AssetSpec spec;
  spec.vertices = 65534;
  spec.morph_targets = 0;
  const Asset a = makeAsset(spec);
  const Loaded m = writeAndLoad(a, true, "short_indices.glb");
  EXPECT_EQ(m.accessors[size_t(onlyPrimitive(m).indices)].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
}

// A clip whose keys are not unit (made by hand, not by the bake) is written
// normalised (in double, then rounded), not spliced as it is.
TEST(GltfWriter, RotationKeysThatAreNotUnitAreNormalised) {
  AssetSpec spec;
  spec.frames = 5;
  Asset a = makeAsset(spec);
  RotationTrack& track = a.animations[0].rotations[1];
  const RotationTrack unit = track;
  for (Eigen::Quaternionf& q : track) q.coeffs() *= 2.5f;
  const Loaded m = writeAndLoad(a, true, "scaled.glb");
  const tinygltf::AnimationChannel& ch = m.animations[0].channels[1];
  ASSERT_EQ(ch.target_node, 1);
  const std::vector<double> q =
      readAccessor(m, m.animations[0].samplers[size_t(ch.sampler)].output);
  ASSERT_EQ(q.size(), 4 * unit.size());
  for (size_t t = 0; t < unit.size(); ++t)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(q[4 * t + size_t(c)], unit[t].coeffs()[c], 2e-7) << t;
}

TEST(GltfWriter, AnimationChannels) {
  AssetSpec spec;
  spec.frames = 5;
  const Asset a = makeAsset(spec);
  const Loaded m = writeAndLoad(a, true, "anim.glb");
  expectAsset(m, a);
  ASSERT_EQ(m.animations.size(), 1u);
  const tinygltf::Animation& anim = m.animations[0];
  const AnimationClip& clip = a.animations[0];
  const int k_count = int(a.skeleton.names.size());
  EXPECT_EQ(anim.name, "walk");
  ASSERT_EQ(anim.channels.size(), size_t(k_count + 2));
  for (int k = 0; k < k_count; ++k) {
    const tinygltf::AnimationChannel& ch = anim.channels[size_t(k)];
    EXPECT_EQ(ch.target_node, k);
    EXPECT_EQ(ch.target_path, "rotation");
    const tinygltf::AnimationSampler& s = anim.samplers[size_t(ch.sampler)];
    EXPECT_EQ(s.interpolation, "LINEAR");
    const tinygltf::Accessor& in = m.accessors[size_t(s.input)];
    EXPECT_EQ(in.minValues, std::vector<double>{0.0});
    EXPECT_EQ(in.maxValues, std::vector<double>{float(clip.times.back())});
    std::vector<double> q = readAccessor(m, s.output);
    ASSERT_EQ(q.size(), 4 * clip.times.size());
    for (size_t t = 0; t < clip.times.size(); ++t) {
      const Eigen::Quaternionf& want = clip.rotations[size_t(k)][t];
      EXPECT_NEAR(q[4 * t + 0], want.x(), 1e-6);
      EXPECT_NEAR(q[4 * t + 3], want.w(), 1e-6);
    }
  }
  const tinygltf::AnimationChannel& tr = anim.channels[size_t(k_count)];
  EXPECT_EQ(tr.target_node, 0);
  EXPECT_EQ(tr.target_path, "translation");
  const tinygltf::AnimationChannel& wc = anim.channels[size_t(k_count + 1)];
  EXPECT_EQ(wc.target_node, k_count);
  EXPECT_EQ(wc.target_path, "weights");
  std::vector<double> w = readAccessor(m, anim.samplers[size_t(wc.sampler)].output);
  ASSERT_EQ(w.size(), clip.times.size() * a.mesh.morph_targets.size());
  for (size_t t = 0; t < clip.times.size(); ++t)
    for (size_t n = 0; n < a.mesh.morph_targets.size(); ++n)
      EXPECT_EQ(w[t * a.mesh.morph_targets.size() + n],
                clip.morph_weights(Eigen::Index(t), Eigen::Index(n)));
  // A .gltf embeds the same buffer, the spliced weight keys joined in.
  const Loaded text = writeAndLoad(a, false, "anim.gltf");
  ASSERT_EQ(text.buffers.size(), 1u);
  EXPECT_EQ(text.buffers[0].data, m.buffers[0].data);
}

TEST(GltfWriter, ByteDeterministic) {
  AssetSpec spec;
  spec.frames = 3;
  const Asset a = makeAsset(spec);
  for (bool binary : {true, false}) {
    WriterOptions options;
    options.binary = binary;
    Result<std::string> first = gltfWriter().serialize(a, options);
    Result<std::string> second = gltfWriter().serialize(makeAsset(spec), options);
    ASSERT_TRUE(first.ok() && second.ok());
    EXPECT_EQ(*first, *second);
  }
}

TEST(GltfWriter, GlbContainerIsWellFormed) {
  Result<std::string> bytes = gltfWriter().serialize(makeAsset({}), WriterOptions{});
  ASSERT_TRUE(bytes.ok());
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, bytes->data() + at, 4);
    return v;
  };
  ASSERT_GE(bytes->size(), 28u);
  EXPECT_EQ(bytes->substr(0, 4), "glTF");
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), bytes->size());
  const uint32_t json_len = u32(12);
  EXPECT_EQ(json_len % 4, 0u);
  EXPECT_EQ(u32(16), 0x4E4F534Au);                 // "JSON"
  EXPECT_EQ(u32(20 + json_len + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(20 + json_len + 8 + u32(20 + json_len), bytes->size());
}

TEST(GltfWriter, RejectsInvalidAssetsWithMessages) {
  auto fails = [](Asset a, const std::string& fragment) {
    Result<std::string> r = gltfWriter().serialize(a, WriterOptions{});
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find(fragment), std::string::npos) << r.message();
  };
  Asset a = makeAsset({});
  a.skeleton.parents[3] = 5;
  fails(a, "joint 3");
  a = makeAsset({});
  a.mesh.joints(2, 1) = 99;
  fails(a, "uses joint 99");
  a = makeAsset({});
  a.mesh.triangles(0, 0) = 12;
  fails(a, "index out of range");
  a = makeAsset({});
  a.mesh.morph_targets[1].deltas.resize(3, 3);
  fails(a, "shape (3,3)");
  a = makeAsset({});
  a.mesh.weights.row(4).setZero();
  fails(a, "no positive skin weight");
  AssetSpec spec;
  spec.frames = 3;
  a = makeAsset(spec);
  a.animations[0].times[2] = a.animations[0].times[1];
  fails(a, "strictly increasing");
  a = makeAsset(spec);
  a.animations[0].morph_weights.resize(3, 5);
  fails(a, "morph weights");
  a = makeAsset({});
  a.skeleton.names[2] = "smpl-export:metadata:7c1e5a90";
  fails(a, "placeholder");
}

TEST(GltfWriter, MergesDuplicateJointsAndMovesZeroWeightsToJointZero) {
  Asset a = makeAsset({});
  a.mesh.joints.row(0) << 4, 4, 7, 2;
  a.mesh.weights.row(0) << 0.25f, 0.25f, 0.5f, 0.f;
  const Loaded m = writeAndLoad(a, true, "duplicates.glb");
  expectSkinWeights(m, a);
  std::vector<double> j = readAccessor(m, onlyPrimitive(m).attributes.at("JOINTS_0"));
  std::vector<double> w = readAccessor(m, onlyPrimitive(m).attributes.at("WEIGHTS_0"));
  EXPECT_EQ(std::vector<double>(j.begin(), j.begin() + 4), (std::vector<double>{4, 0, 7, 0}));
  EXPECT_EQ(std::vector<double>(w.begin(), w.begin() + 4), (std::vector<double>{0.5, 0, 0.5, 0}));
}

TEST(WriterRegistry, PicksWriterByExtension) {
  EXPECT_EQ(writerForPath("out/body.glb"), &gltfWriter());
  EXPECT_EQ(writerForPath("body.GLTF"), &gltfWriter());
  EXPECT_EQ(writerForPath("body.obj"), nullptr);
  EXPECT_EQ(writerForPath("glb"), nullptr);
#if __has_include("writers/fbx/fbx_writer.h")
  ASSERT_NE(writerForPath("body.fbx"), nullptr);
  EXPECT_STRNE(writerForPath("body.fbx")->name(), gltfWriter().name());
#endif
}

}  // namespace
}  // namespace smpl
