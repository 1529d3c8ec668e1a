#include "plugins/fbx/fbx_scene.h"

#include <cmath>

#include "plugins/fbx/fbx_scene_internal.h"

namespace smpl {

const char kFbxCreationTime[] = "1970-01-01 10:00:00:000";
const char kFbxCreator[] = "smpl-export";

namespace {

using fbx::SceneContext;

// The FileId that readers accept together with kFbxCreationTime (the pair
// Blender writes for the same reason: fixed, reproducible files).
const char kFileId[] = "\x28\xb3\x2a\xeb\xb6\x24\xcc\xc2\xbf\xc8\xb0\x2a\xa9\x2b\xfc\xf1";

std::string sizeText(Eigen::Index rows, Eigen::Index cols) {
  return "(" + std::to_string(rows) + "," + std::to_string(cols) + ")";
}

Status checkSkeleton(const Skeleton& s) {
  const size_t k = s.names.size();
  if (k == 0) return makeError("FBX: asset has no joints");
  if (s.parents.size() != k)
    return makeError("FBX: skeleton has " + std::to_string(k) + " names but " +
                     std::to_string(s.parents.size()) + " parents");
  for (size_t j = 0; j < k; ++j)
    if (s.parents[j] < -1 || s.parents[j] >= static_cast<int>(j))
      return makeError("FBX: joint " + std::to_string(j) + " has parent " +
                       std::to_string(s.parents[j]) + "; expected -1 <= parent < joint");
  if (s.rest_local.rows() != Eigen::Index(k) || s.rest_local.cols() != 3 ||
      s.rest_world.rows() != Eigen::Index(k) || s.rest_world.cols() != 3)
    return makeError("FBX: rest_local " + sizeText(s.rest_local.rows(), s.rest_local.cols()) +
                     " / rest_world " + sizeText(s.rest_world.rows(), s.rest_world.cols()) +
                     "; expected (" + std::to_string(k) + ",3)");
  return Status::success();
}

Status checkMesh(const SkinnedMesh& m, int joints) {
  const Eigen::Index v = m.positions.rows();
  if (v == 0 || m.positions.cols() != 3)
    return makeError("FBX: mesh positions " + sizeText(v, m.positions.cols()) +
                     "; expected (V,3), V > 0");
  if (m.normals.rows() != 0 && (m.normals.rows() != v || m.normals.cols() != 3))
    return makeError("FBX: mesh normals " + sizeText(m.normals.rows(), m.normals.cols()) +
                     "; expected (" + std::to_string(v) + ",3)");
  if (m.uvs.rows() != 0 && (m.uvs.rows() != v || m.uvs.cols() != 2))
    return makeError("FBX: mesh uvs " + sizeText(m.uvs.rows(), m.uvs.cols()) + "; expected (" +
                     std::to_string(v) + ",2)");
  if (m.triangles.cols() != 3 || m.triangles.rows() == 0)
    return makeError("FBX: mesh triangles " + sizeText(m.triangles.rows(), m.triangles.cols()) +
                     "; expected (F,3), F > 0");
  if (m.triangles.minCoeff() < 0 || m.triangles.maxCoeff() >= v)
    return makeError("FBX: triangle index out of range [0," + std::to_string(v) + ")");
  if (m.joints.rows() != v || m.weights.rows() != v || m.joints.cols() != m.weights.cols())
    return makeError("FBX: skin joints " + sizeText(m.joints.rows(), m.joints.cols()) +
                     " / weights " + sizeText(m.weights.rows(), m.weights.cols()) +
                     "; expected equal shapes (" + std::to_string(v) + ",M)");
  if (m.joints.size() > 0 && (m.joints.minCoeff() < 0 || m.joints.maxCoeff() >= joints))
    return makeError("FBX: skin joint index out of range [0," + std::to_string(joints) + ")");
  for (const MorphTarget& t : m.morph_targets)
    if (t.deltas.rows() != v || t.deltas.cols() != 3)
      return makeError("FBX: morph target '" + t.name + "' deltas " +
                       sizeText(t.deltas.rows(), t.deltas.cols()) + "; expected (" +
                       std::to_string(v) + ",3)");
  return Status::success();
}

Status checkClip(const AnimationClip& c, size_t joints, size_t targets) {
  const size_t t = c.times.size();
  const std::string where = "FBX: animation '" + c.name + "': ";
  if (!(c.fps > 0) || !std::isfinite(c.fps)) return makeError(where + "fps must be positive");
  for (size_t i = 0; i < t; ++i)
    if (!std::isfinite(c.times[i]) || (i > 0 && c.times[i] < c.times[i - 1]))
      return makeError(where + "times must be finite and non-decreasing");
  if (c.rotations.size() != joints)
    return makeError(where + std::to_string(c.rotations.size()) + " rotation tracks; expected " +
                     std::to_string(joints));
  for (size_t k = 0; k < c.rotations.size(); ++k) {
    if (c.rotations[k].size() != t)
      return makeError(where + "joint " + std::to_string(k) + " has " +
                       std::to_string(c.rotations[k].size()) + " rotation keys; expected " +
                       std::to_string(t));
    for (const Eigen::Quaterniond& q : c.rotations[k])
      if (!std::isfinite(q.squaredNorm()) || q.squaredNorm() < 1e-12)
        return makeError(where + "joint " + std::to_string(k) +
                         " has a zero or non-finite rotation");
  }
  for (const Eigen::Vector3d& p : c.root_translation)
    if (!p.allFinite()) return makeError(where + "non-finite root translation");
  if (!c.root_translation.empty() && c.root_translation.size() != t)
    return makeError(where + std::to_string(c.root_translation.size()) +
                     " root translations; expected " + std::to_string(t));
  if (c.morph_weights.size() != 0 && (c.morph_weights.rows() != Eigen::Index(t) ||
                                      c.morph_weights.cols() != Eigen::Index(targets)))
    return makeError(where + "morph weights " +
                     sizeText(c.morph_weights.rows(), c.morph_weights.cols()) + "; expected (" +
                     std::to_string(t) + "," + std::to_string(targets) + ")");
  return Status::success();
}

Status checkInput(const Asset& a, const WriterOptions& o) {
  if (o.fbx_units != "m" && o.fbx_units != "cm")
    return makeError("FBX: units '" + o.fbx_units + "'; expected m or cm");
  if (o.fbx_version != 7400 && o.fbx_version != 7500)
    return makeError("FBX: version " + std::to_string(o.fbx_version) + "; expected 7400 or 7500");
  Status s = checkSkeleton(a.skeleton);
  if (s.ok()) s = checkMesh(a.mesh, static_cast<int>(a.skeleton.names.size()));
  for (size_t i = 0; s.ok() && i < a.animations.size(); ++i)
    s = checkClip(a.animations[i], a.skeleton.names.size(), a.mesh.morph_targets.size());
  return s;
}

FbxNode headerExtension(int version) {
  FbxNode h("FBXHeaderExtension");
  h.add("FBXHeaderVersion").addInt32(1003);
  h.add("FBXVersion").addInt32(version);
  h.add("EncryptionType").addInt32(0);
  FbxNode& ts = h.add("CreationTimeStamp");
  const int stamp[][2] = {{1000, 0}, {1970, 1}, {1, 2}, {1, 3}, {10, 4}, {0, 5}, {0, 6}, {0, 7}};
  const char* fields[] = {"Version", "Year",   "Month",  "Day",
                          "Hour",    "Minute", "Second", "Millisecond"};
  for (const auto& f : stamp) ts.add(fields[f[1]]).addInt32(f[0]);
  h.add("Creator").addString(kFbxCreator);
  FbxNode& info = h.add("SceneInfo");
  info.addString(fbx::nameClass("GlobalInfo", "SceneInfo")).addString("UserData");
  info.add("Type").addString("UserData");
  info.add("Version").addInt32(100);
  FbxNode& meta = info.add("MetaData");
  meta.add("Version").addInt32(100);
  for (const char* key : {"Title", "Subject", "Author", "Keywords", "Revision", "Comment"})
    meta.add(key).addString("");
  FbxNode& p70 = info.add("Properties70");
  fbx::addP(p70, "Original", "Compound", "", "");
  fbx::pString(p70, "Original|ApplicationName", kFbxCreator);
  fbx::addP(p70, "LastSaved", "Compound", "", "");
  fbx::pString(p70, "LastSaved|ApplicationName", kFbxCreator);
  return h;
}

// FBX TimeMode enum values for the standard rates; 14 means custom.
int timeModeFor(double fps) {
  const std::pair<double, int> modes[] = {{120, 1}, {100, 2}, {60, 3},  {50, 4},  {48, 5},
                                          {30, 6},  {25, 10}, {24, 11}, {96, 15}, {72, 16}};
  for (const auto& m : modes)
    if (std::abs(fps - m.first) < 1e-6) return m.second;
  return 14;
}

FbxNode globalSettings(const SceneContext& ctx) {
  const Asset& a = ctx.asset;
  double fps = a.animations.empty() ? 30.0 : a.animations[0].fps;
  double stop = 1.0;
  if (!a.animations.empty() && !a.animations[0].times.empty()) stop = a.animations[0].times.back();
  double unit = ctx.options.fbx_units == "cm" ? 1.0 : 100.0;  // centimetres per file unit
  FbxNode g("GlobalSettings");
  g.add("Version").addInt32(1000);
  FbxNode& p = g.add("Properties70");
  fbx::pInt(p, "UpAxis", 1);
  fbx::pInt(p, "UpAxisSign", 1);
  fbx::pInt(p, "FrontAxis", 2);
  fbx::pInt(p, "FrontAxisSign", 1);
  fbx::pInt(p, "CoordAxis", 0);
  fbx::pInt(p, "CoordAxisSign", 1);
  fbx::pInt(p, "OriginalUpAxis", 1);
  fbx::pInt(p, "OriginalUpAxisSign", 1);
  fbx::pDouble(p, "UnitScaleFactor", unit);
  fbx::pDouble(p, "OriginalUnitScaleFactor", unit);
  fbx::pColor(p, "AmbientColor", 0, 0, 0);
  fbx::pString(p, "DefaultCamera", "Producer Perspective");
  fbx::pEnum(p, "TimeMode", timeModeFor(fps));
  fbx::pTime(p, "TimeSpanStart", 0);
  fbx::pTime(p, "TimeSpanStop", fbx::secondsToKTime(stop));
  fbx::pDouble(p, "CustomFrameRate", fps);
  return g;
}

FbxNode documents(SceneContext& ctx) {
  FbxNode d("Documents");
  d.add("Count").addInt32(1);
  FbxNode& doc = d.add("Document");
  doc.addInt64(ctx.ids.id("document")).addString("").addString("Scene");
  FbxNode& p = doc.add("Properties70");
  fbx::addP(p, "SourceObject", "object", "", "");
  fbx::pString(p, "ActiveAnimStackName",
               ctx.asset.animations.empty() ? "" : ctx.asset.animations[0].name);
  doc.add("RootNode").addInt64(0);
  return d;
}

FbxNode definitions(const SceneContext& ctx) {
  FbxNode d("Definitions");
  int total = 1;  // GlobalSettings
  for (const auto& entry : ctx.type_counts) total += entry.second;
  d.add("Version").addInt32(100);
  d.add("Count").addInt32(total);
  d.add("ObjectType").addString("GlobalSettings").add("Count").addInt32(1);
  for (const auto& entry : ctx.type_counts)
    d.add("ObjectType").addString(entry.first).add("Count").addInt32(entry.second);
  return d;
}

FbxNode takes(const Asset& a) {
  FbxNode t("Takes");
  t.add("Current").addString(a.animations.empty() ? "" : a.animations[0].name);
  for (const AnimationClip& c : a.animations) {
    int64_t start = c.times.empty() ? 0 : fbx::secondsToKTime(c.times.front());
    int64_t stop = c.times.empty() ? 0 : fbx::secondsToKTime(c.times.back());
    FbxNode& take = t.add("Take");
    take.addString(c.name);
    take.add("FileName").addString(c.name + ".tak");
    take.add("LocalTime").addInt64(start).addInt64(stop);
    take.add("ReferenceTime").addInt64(start).addInt64(stop);
  }
  return t;
}

}  // namespace

Result<std::vector<FbxNode>> buildFbxScene(const Asset& asset, const WriterOptions& options) {
  Status ok = checkInput(asset, options);
  if (!ok) return ok.error();
  SceneContext ctx(asset, options);
  ctx.scale = options.fbx_units == "cm" ? 100.0 : 1.0;
  fbx::buildMeshObjects(ctx);
  fbx::buildSkeletonObjects(ctx);
  fbx::buildSkinObjects(ctx);
  fbx::buildMorphObjects(ctx);
  fbx::buildAnimationObjects(ctx);

  std::vector<FbxNode> top;
  top.push_back(headerExtension(options.fbx_version));
  top.emplace_back("FileId");
  top.back().addRaw(std::string(kFileId, 16));
  top.emplace_back("CreationTime");
  top.back().addString(kFbxCreationTime);
  top.emplace_back("Creator");
  top.back().addString(kFbxCreator);
  top.push_back(globalSettings(ctx));
  top.push_back(documents(ctx));
  top.emplace_back("References");
  top.push_back(definitions(ctx));
  top.push_back(std::move(ctx.objects));
  top.push_back(std::move(ctx.connections));
  top.push_back(takes(asset));
  return top;
}

}  // namespace smpl
