// Helpers shared by the FBX scene builders (fbx_scene_internal.h).
#include <cmath>

#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {

int64_t secondsToKTime(double seconds) {
  return static_cast<int64_t>(std::llround(seconds * static_cast<double>(kKTimePerSecond)));
}

int64_t IdTable::id(const std::string& key) {
  const std::string full = prefix_ + key;
  auto it = by_key_.find(full);
  if (it != by_key_.end()) return it->second;
  // FNV-1a over the key; ids stay positive, non-zero (0 is the scene root)
  // and below 2^53 so tools that parse ids as doubles keep them exact.
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : full) h = (h ^ c) * 1099511628211ULL;
  int64_t v = static_cast<int64_t>(h & ((1ULL << 52) - 1)) + 1000;
  while (used_.count(v)) ++v;  // deterministic: keys are requested in a fixed order
  used_.insert(v);
  by_key_[full] = v;
  return v;
}

std::string nameClass(const std::string& name, const char* cls) {
  return name + std::string("\x00\x01", 2) + cls;
}

FbxNode& addP(FbxNode& p70, const std::string& name, const char* type, const char* label,
              const char* flags) {
  FbxNode& p = p70.add("P");
  p.addString(name).addString(type).addString(label).addString(flags);
  return p;
}

void pInt(FbxNode& p70, const std::string& name, int32_t v) {
  addP(p70, name, "int", "Integer", "").addInt32(v);
}
void pEnum(FbxNode& p70, const std::string& name, int32_t v) {
  addP(p70, name, "enum", "", "").addInt32(v);
}
void pDouble(FbxNode& p70, const std::string& name, double v) {
  addP(p70, name, "double", "Number", "").addDouble(v);
}
void pNumber(FbxNode& p70, const std::string& name, double v, bool animatable) {
  addP(p70, name, "Number", "", animatable ? "A" : "").addDouble(v);
}
void pTime(FbxNode& p70, const std::string& name, int64_t ktime) {
  addP(p70, name, "KTime", "Time", "").addInt64(ktime);
}
void pString(FbxNode& p70, const std::string& name, const std::string& v) {
  addP(p70, name, "KString", "", "").addString(v);
}
void pColor(FbxNode& p70, const std::string& name, double r, double g, double b) {
  addP(p70, name, "ColorRGB", "Color", "").addDouble(r).addDouble(g).addDouble(b);
}
void pVector(FbxNode& p70, const std::string& name, const char* type, const char* label,
             const char* flags, double x, double y, double z) {
  addP(p70, name, type, label, flags).addDouble(x).addDouble(y).addDouble(z);
}

void addModelBody(FbxNode& model, double x, double y, double z) {
  addModelBody(model, Eigen::Vector3d(x, y, z), Eigen::Vector3d::Zero());
}

void addModelBody(FbxNode& model, const Eigen::Vector3d& t, const Eigen::Vector3d& r) {
  model.add("Version").addInt32(232);
  FbxNode& p = model.add("Properties70");
  pVector(p, "Lcl Translation", "Lcl Translation", "", "A", t.x(), t.y(), t.z());
  pVector(p, "Lcl Rotation", "Lcl Rotation", "", "A", r.x(), r.y(), r.z());
  pVector(p, "Lcl Scaling", "Lcl Scaling", "", "A", 1, 1, 1);
  pInt(p, "DefaultAttributeIndex", 0);
  pEnum(p, "InheritType", 1);
  model.add("MultiLayer").addInt32(0);
  model.add("MultiTake").addInt32(0);
  model.add("Shading").addBool(true);
  model.add("Culling").addString("CullingOff");
}

std::vector<double> translationMatrix(double x, double y, double z) {
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1};
}

FbxNode& SceneContext::addObject(const char* node_type, int64_t id, const std::string& name,
                                 const char* cls, const char* subclass) {
  bool counted = false;
  for (auto& entry : type_counts)
    if (entry.first == node_type) {
      ++entry.second;
      counted = true;
    }
  if (!counted) type_counts.emplace_back(node_type, 1);
  FbxNode& n = objects.add(node_type);
  n.addInt64(id).addString(nameClass(name, cls)).addString(subclass);
  return n;
}

const std::string& SceneContext::bodyName() const {
  static const std::string fallback = "body";
  if (!body_name.empty()) return body_name;
  return asset.name.empty() ? fallback : asset.name;
}

const std::string& SceneContext::meshName() const {
  return mesh_name.empty() ? bodyName() : mesh_name;
}

void SceneContext::takeShared(SceneContext& from) {
  ids = std::move(from.ids);
  objects = std::move(from.objects);
  connections = std::move(from.connections);
  type_counts = std::move(from.type_counts);
}

void SceneContext::connectOO(int64_t child, int64_t parent) {
  connections.add("C").addString("OO").addInt64(child).addInt64(parent);
}

void SceneContext::connectOP(int64_t child, int64_t parent, const std::string& property) {
  connections.add("C").addString("OP").addInt64(child).addInt64(parent).addString(property);
}

}  // namespace fbx
}  // namespace smpl
