// Morph targets as one BlendShape deformer with one BlendShapeChannel and
// one Shape geometry per target (fbx_scene_internal.h). Blender names shape
// keys after the Shape geometry, Unity after the channel: both carry the
// target name.
#include <map>

#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

// Sparse deltas: the vertices that move. Never empty (Unity crashes on empty
// shapes): a target without a non-zero delta keeps its largest-magnitude
// vertex, whose delta is then tiny or zero.
void sparseDeltas(const MorphDeltas& deltas, double scale, std::vector<int32_t>& indexes,
                  std::vector<double>& vertices) {
  indexes.clear();
  vertices.clear();
  for (Eigen::Index v = 0; v < deltas.rows(); ++v) {
    if (deltas(v, 0) == 0.0f && deltas(v, 1) == 0.0f && deltas(v, 2) == 0.0f) continue;
    indexes.push_back(static_cast<int32_t>(v));
    for (int c = 0; c < 3; ++c) vertices.push_back(double(deltas(v, c)) * scale);
  }
  if (!indexes.empty()) return;
  Eigen::Index largest = 0;
  deltas.rowwise().squaredNorm().maxCoeff(&largest);
  indexes.push_back(static_cast<int32_t>(largest));
  for (int c = 0; c < 3; ++c) vertices.push_back(double(deltas(largest, c)) * scale);
}

// The zero normal deltas of a shape of `count` values: one shared payload
// per count (encoded, hashed and compressed once, however many shapes).
const FbxProperty& zeroNormals(std::map<size_t, FbxProperty>* zeros, size_t count) {
  auto it = zeros->find(count);
  if (it == zeros->end())
    it = zeros->emplace(count, fbxSharedDoubleArray(std::vector<double>(count, 0.0))).first;
  return it->second;
}

void addTarget(SceneContext& ctx, size_t i, int64_t blend_shape,
               std::map<size_t, FbxProperty>* zeros) {
  const MorphTarget& target = ctx.asset.mesh.morph_targets[i];
  std::vector<int32_t> indexes;
  std::vector<double> vertices;
  sparseDeltas(target.deltas, ctx.scale, indexes, vertices);

  int64_t shape = ctx.ids.id("shape/" + std::to_string(i));
  FbxNode& g = ctx.addObject("Geometry", shape, ctx.ns + target.name, "Geometry", "Shape");
  g.add("Properties70");
  g.add("Version").addInt32(100);
  g.add("Indexes").addInt32Array(indexes);
  g.add("Vertices").addDoubleArray(vertices);
  // Normal deltas: zero keeps the rest normals (correctives are small), and
  // costs almost nothing deflated; Assimp rejects shapes without them.
  g.add("Normals").addShared(zeroNormals(zeros, vertices.size()));

  int64_t channel = ctx.ids.id("channel/" + std::to_string(i));
  ctx.blend_channels.push_back(channel);
  FbxNode& c =
      ctx.addObject("Deformer", channel, ctx.ns + target.name, "SubDeformer", "BlendShapeChannel");
  c.add("Version").addInt32(100);
  c.add("DeformPercent").addDouble(100.0 * target.rest_weight);  // rest pose weight (unit encoding)
  c.add("FullWeights").addDoubleArray({100.0});  // one shape per channel, full at 100%

  ctx.connectOO(channel, blend_shape);
  ctx.connectOO(shape, channel);
}

}  // namespace

void buildMorphObjects(SceneContext& ctx) {
  const auto& targets = ctx.asset.mesh.morph_targets;
  if (targets.empty()) return;
  const std::string& name = ctx.bodyName();
  int64_t blend_shape = ctx.ids.id("blendshape");
  FbxNode& d =
      ctx.addObject("Deformer", blend_shape, name + "_blendshapes", "Deformer", "BlendShape");
  d.add("Version").addInt32(100);
  ctx.connectOO(blend_shape, ctx.mesh_geometry);
  std::map<size_t, FbxProperty> zeros;
  for (size_t i = 0; i < targets.size(); ++i) addTarget(ctx, i, blend_shape, &zeros);
}

}  // namespace fbx
}  // namespace smpl
