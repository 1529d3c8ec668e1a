// Mesh Geometry, its Model and one Material (fbx_scene_internal.h).
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

// Vertices, then polygons: each triangle's last index is written as -(i+1).
void addTopology(FbxNode& geom, const SkinnedMesh& m, double scale) {
  std::vector<double> vertices(m.positions.size());
  for (Eigen::Index v = 0; v < m.positions.rows(); ++v)
    for (int c = 0; c < 3; ++c) vertices[3 * v + c] = double(m.positions(v, c)) * scale;
  geom.add("Vertices").addDoubleArray(vertices);
  std::vector<int32_t> pvi(m.triangles.size());
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f) {
    pvi[3 * f] = m.triangles(f, 0);
    pvi[3 * f + 1] = m.triangles(f, 1);
    pvi[3 * f + 2] = -m.triangles(f, 2) - 1;
  }
  geom.add("PolygonVertexIndex").addInt32Array(pvi);
}

FbxNode& layerElement(FbxNode& geom, const char* type, int version, const char* mapping,
                      const char* reference, const char* name = "") {
  FbxNode& e = geom.add(type);
  e.addInt32(0);
  e.add("Version").addInt32(version);
  e.add("Name").addString(name);
  e.add("MappingInformationType").addString(mapping);
  e.add("ReferenceInformationType").addString(reference);
  return e;
}

// Normals per polygon corner, copied from the corner's vertex.
void addNormals(FbxNode& geom, const SkinnedMesh& m) {
  std::vector<double> normals(m.triangles.size() * 3);
  for (Eigen::Index i = 0; i < m.triangles.size(); ++i) {
    int v = m.triangles(i / 3, i % 3);
    for (int c = 0; c < 3; ++c) normals[3 * i + c] = m.normals(v, c);
  }
  layerElement(geom, "LayerElementNormal", 101, "ByPolygonVertex", "Direct")
      .add("Normals")
      .addDoubleArray(normals);
}

// UVs indexed per corner by the corner's vertex: the UV array is the
// per-vertex table as is (v up, like OBJ and FBX).
void addUvs(FbxNode& geom, const SkinnedMesh& m) {
  std::vector<double> uv(m.uvs.size());
  for (Eigen::Index v = 0; v < m.uvs.rows(); ++v)
    for (int c = 0; c < 2; ++c) uv[2 * v + c] = m.uvs(v, c);
  std::vector<int32_t> index(m.triangles.size());
  for (Eigen::Index i = 0; i < m.triangles.size(); ++i) index[i] = m.triangles(i / 3, i % 3);
  FbxNode& e =
      layerElement(geom, "LayerElementUV", 101, "ByPolygonVertex", "IndexToDirect", "UVMap");
  e.add("UV").addDoubleArray(uv);
  e.add("UVIndex").addInt32Array(index);
}

void addLayer(FbxNode& geom, const SkinnedMesh& m) {
  FbxNode& layer = geom.add("Layer");
  layer.addInt32(0);
  layer.add("Version").addInt32(100);
  std::vector<const char*> types;
  if (m.normals.rows() > 0) types.push_back("LayerElementNormal");
  types.push_back("LayerElementMaterial");
  if (m.uvs.rows() > 0) types.push_back("LayerElementUV");
  for (const char* type : types) {
    FbxNode& e = layer.add("LayerElement");
    e.add("Type").addString(type);
    e.add("TypedIndex").addInt32(0);
  }
}

void addMeshGeometry(SceneContext& ctx) {
  const SkinnedMesh& m = ctx.asset.mesh;
  ctx.mesh_geometry = ctx.ids.id("geometry/mesh");
  FbxNode& geom = ctx.addObject("Geometry", ctx.mesh_geometry, ctx.meshName(), "Geometry", "Mesh");
  geom.add("Properties70");
  geom.add("GeometryVersion").addInt32(124);
  addTopology(geom, m, ctx.scale);
  if (m.normals.rows() > 0) addNormals(geom, m);
  if (m.uvs.rows() > 0) addUvs(geom, m);
  layerElement(geom, "LayerElementMaterial", 101, "AllSame", "IndexToDirect")
      .add("Materials")
      .addInt32Array({0});
  addLayer(geom, m);
}

void addMeshModel(SceneContext& ctx) {
  ctx.mesh_model = ctx.ids.id("model/mesh");
  FbxNode& model = ctx.addObject("Model", ctx.mesh_model, ctx.meshName(), "Model", "Mesh");
  addModelBody(model, 0, 0, 0);
}

void addMaterial(SceneContext& ctx) {
  int64_t id = ctx.ids.id("material/0");
  FbxNode& mat = ctx.addObject("Material", id, ctx.bodyName() + "_material", "Material", "");
  mat.add("Version").addInt32(102);
  mat.add("ShadingModel").addString("lambert");
  mat.add("MultiLayer").addInt32(0);
  FbxNode& p = mat.add("Properties70");
  addP(p, "DiffuseColor", "Color", "", "A").addDouble(0.8).addDouble(0.8).addDouble(0.8);
  addP(p, "DiffuseFactor", "Number", "", "A").addDouble(1.0);
  ctx.connectOO(id, ctx.mesh_model);
}

}  // namespace

void buildMeshObjects(SceneContext& ctx) {
  addMeshGeometry(ctx);
  addMeshModel(ctx);
  ctx.connectOO(ctx.mesh_model, 0);
  ctx.connectOO(ctx.mesh_geometry, ctx.mesh_model);
  addMaterial(ctx);
}

}  // namespace fbx
}  // namespace smpl
