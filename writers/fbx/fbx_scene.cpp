#include "writers/fbx/fbx_scene.h"

#include <algorithm>
#include <cmath>

#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {

const char kFbxCreationTime[] = "1970-01-01 10:00:00:000";
const char kFbxCreator[] = "smpl-export";

namespace {

using fbx::SceneContext;

// The FileId that readers accept together with kFbxCreationTime (the pair
// Blender writes for the same reason: fixed, reproducible files).
const char kFileId[] = "\x28\xb3\x2a\xeb\xb6\x24\xcc\xc2\xbf\xc8\xb0\x2a\xa9\x2b\xfc\xf1";

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

// The file's timeline: its animation's name (the take and stack), rate and
// last key time in seconds.
struct Timeline {
  std::string name;
  double fps = 30.0;
  double stop = 1.0;
};

Timeline assetTimeline(const Asset& a) {
  Timeline t;
  if (!a.animations.empty()) {
    t.name = a.animations[0].name;
    t.fps = a.animations[0].fps;
    if (!a.animations[0].times.empty()) t.stop = a.animations[0].times.back();
  }
  return t;
}

FbxNode globalSettings(const Timeline& time, const WriterOptions& options) {
  const double fps = time.fps, stop = time.stop;
  double unit = options.fbx_units == "cm" ? 1.0 : 100.0;  // centimetres per file unit
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

FbxNode documents(SceneContext& ctx, const std::string& stack_name) {
  FbxNode d("Documents");
  d.add("Count").addInt32(1);
  FbxNode& doc = d.add("Document");
  doc.addInt64(ctx.ids.id("document")).addString("").addString("Scene");
  FbxNode& p = doc.add("Properties70");
  fbx::addP(p, "SourceObject", "object", "", "");
  fbx::pString(p, "ActiveAnimStackName", stack_name);
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

// One take per animation stack: its name and [start, stop] in KTime.
struct Take {
  std::string name;
  int64_t start = 0, stop = 0;
};

FbxNode takes(const std::string& current, const std::vector<Take>& list) {
  FbxNode t("Takes");
  t.add("Current").addString(current);
  for (const Take& c : list) {
    FbxNode& take = t.add("Take");
    take.addString(c.name);
    take.add("FileName").addString(c.name + ".tak");
    take.add("LocalTime").addInt64(c.start).addInt64(c.stop);
    take.add("ReferenceTime").addInt64(c.start).addInt64(c.stop);
  }
  return t;
}

std::vector<Take> assetTakes(const Asset& a) {
  std::vector<Take> list;
  for (const AnimationClip& c : a.animations) {
    int64_t start = c.times.empty() ? 0 : fbx::secondsToKTime(c.times.front());
    int64_t stop = c.times.empty() ? 0 : fbx::secondsToKTime(c.times.back());
    list.push_back({c.name, start, stop});
  }
  return list;
}

// The top-level nodes around the built objects (the layout in fbx_scene.h).
std::vector<FbxNode> fileNodes(SceneContext& ctx, const Timeline& time,
                               const std::vector<Take>& take_list) {
  const WriterOptions& options = ctx.options;
  std::vector<FbxNode> top;
  top.push_back(headerExtension(options.fbx_version));
  top.emplace_back("FileId");
  top.back().addRaw(std::string(kFileId, 16));
  top.emplace_back("CreationTime");
  top.back().addString(kFbxCreationTime);
  top.emplace_back("Creator");
  top.back().addString(kFbxCreator);
  top.push_back(globalSettings(time, options));
  top.push_back(documents(ctx, time.name));
  top.emplace_back("References");
  top.push_back(definitions(ctx));
  top.push_back(std::move(ctx.objects));
  top.push_back(std::move(ctx.connections));
  top.push_back(takes(time.name, take_list));
  return top;
}

}  // namespace

Result<std::vector<FbxNode>> buildFbxScene(const Asset& asset, const WriterOptions& options) {
  Status ok = fbx::validateInput(asset, options);
  if (!ok) return ok.error();
  SceneContext ctx(asset, options);
  ctx.scale = options.fbx_units == "cm" ? 100.0 : 1.0;
  fbx::buildMeshObjects(ctx);
  fbx::buildSkeletonObjects(ctx);
  fbx::buildSkinObjects(ctx);
  fbx::buildMorphObjects(ctx);
  fbx::buildAnimationObjects(ctx);
  return fileNodes(ctx, assetTimeline(asset), assetTakes(asset));
}

Result<std::vector<FbxNode>> buildFbxSceneFile(const SceneAsset& scene,
                                               const WriterOptions& options) {
  if (scene.bodies.empty()) return makeError("FBX writer: a scene without bodies");
  for (const SceneBody& body : scene.bodies)  // the same rules as a one-body file, per body
    if (Status st = fbx::validateInput(body.asset, options); !st)
      return makeError("body '" + body.asset.name + "': " + st.message());
  SceneContext ctx(scene.bodies.front().asset, options);
  ctx.scale = options.fbx_units == "cm" ? 100.0 : 1.0;
  Timeline time{scene.name, scene.fps,
                double(std::max<int64_t>(scene.end_frame - scene.first_frame - 1, 0)) / scene.fps};
  const int64_t stop = fbx::secondsToKTime(time.stop);
  const int64_t layer = fbx::addAnimationLayer(ctx, "scene", scene.name, 0, stop);
  for (size_t i = 0; i < scene.bodies.size(); ++i)
    fbx::buildSceneBody(ctx, scene.bodies[i], i, layer, scene.fps);
  if (scene.camera.present()) fbx::buildSceneCamera(ctx, scene.camera, layer);
  return fileNodes(ctx, time, {{scene.name, 0, stop}});
}

}  // namespace smpl
