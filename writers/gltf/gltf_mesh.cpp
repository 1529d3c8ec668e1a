// glTF writer stage: the mesh and its primitive: the streams as plain
// accessors or KHR_draco_mesh_compression, and the morph targets with their
// rest weights and names (gltf_stages.h).
#include <tiny_gltf.h>

#include <string>

#include "writers/gltf/gltf_draco.h"
#include "writers/gltf/gltf_morphs.h"
#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {
namespace {

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

}  // namespace

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

}  // namespace gltf
}  // namespace smpl
