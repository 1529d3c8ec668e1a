// Shared pieces of the Asset -> FBX node tree builder (fbx_scene*.cpp):
// object ids, Properties70 helpers, and the context the object builders
// fill. Not a public interface.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "exporter/asset.h"
#include "exporter/scene_asset.h"
#include "writers/fbx/fbx_encoder.h"
#include "writers/writer.h"

namespace smpl {
namespace fbx {

// FBX time unit: ticks per second.
constexpr int64_t kKTimePerSecond = 46186158000LL;

int64_t secondsToKTime(double seconds);

// Object ids derived from stable keys ("joint/3", "shape/12"), so the same
// asset always gets the same ids, independent of build order elsewhere.
class IdTable {
 public:
  int64_t id(const std::string& key);
  // Prepended to every key from now on: a scene's body i builds its objects
  // under "body/<i>/" with the one-body keys, so their ids never meet.
  void setPrefix(const std::string& prefix) { prefix_ = prefix; }

 private:
  std::string prefix_;
  std::map<std::string, int64_t> by_key_;
  std::set<int64_t> used_;
};

// Binary FBX object names are "name\x00\x01Class".
std::string nameClass(const std::string& name, const char* cls);

// Properties70 "P" records: name, type, label, flags, values.
FbxNode& addP(FbxNode& p70, const std::string& name, const char* type, const char* label,
              const char* flags);
void pInt(FbxNode& p70, const std::string& name, int32_t v);
void pEnum(FbxNode& p70, const std::string& name, int32_t v);
void pDouble(FbxNode& p70, const std::string& name, double v);
void pNumber(FbxNode& p70, const std::string& name, double v, bool animatable);
void pTime(FbxNode& p70, const std::string& name, int64_t ktime);
void pString(FbxNode& p70, const std::string& name, const std::string& v);
void pColor(FbxNode& p70, const std::string& name, double r, double g, double b);
// Vector-valued property with an explicit type ("Lcl Translation", "Vector3D").
void pVector(FbxNode& p70, const std::string& name, const char* type, const char* label,
             const char* flags, double x, double y, double z);

// The body of a Model object (the mesh's and each joint's): Version, the
// Properties70 (Lcl Translation x y z, no rotation, unit scale, attribute 0,
// InheritType 1) and the display flags.
void addModelBody(FbxNode& model, double x, double y, double z);
// The same with a rest rotation: Euler XYZ degrees (a camera's first key).
void addModelBody(FbxNode& model, const Eigen::Vector3d& translation,
                  const Eigen::Vector3d& rotation_degrees);

// 4x4 column-major matrix (FBX order: translation in elements 12..14).
std::vector<double> translationMatrix(double x, double y, double z);

struct SceneContext {
  const Asset& asset;
  const WriterOptions& options;
  double scale = 1.0;  // model metres -> file units
  IdTable ids;
  FbxNode objects{"Objects"};
  FbxNode connections{"Connections"};
  std::vector<std::pair<std::string, int>> type_counts;  // Definitions, first-use order

  // Names: a one-body file leaves them empty (the asset's name, or "body";
  // joint and target names as they are). A scene's body sets its name, its
  // mesh's ("<body>_mesh") and the namespace "<body>:" that its joint,
  // cluster, shape and channel names carry, so every name is unique.
  std::string body_name, mesh_name, ns;
  int64_t skeleton_parent = 0;  // the root joint's parent: the scene root, or the body's node

  int64_t mesh_model = 0;
  int64_t mesh_geometry = 0;
  std::vector<int64_t> joint_models;
  std::vector<int64_t> blend_channels;  // one per morph target

  SceneContext(const Asset& a, const WriterOptions& o) : asset(a), options(o) {}

  const std::string& bodyName() const;  // body_name, else the asset's name, else "body"
  const std::string& meshName() const;  // mesh_name, else bodyName()
  // The objects, connections, ids and counts built so far move from `from`
  // (a scene's builders run one context per body over one growing file).
  void takeShared(SceneContext& from);

  // Adds an object node under Objects and counts it for Definitions.
  FbxNode& addObject(const char* node_type, int64_t id, const std::string& name, const char* cls,
                     const char* subclass);
  void connectOO(int64_t child, int64_t parent);
  void connectOP(int64_t child, int64_t parent, const std::string& property);
};

// Checks sizes and index ranges of the asset and the options (fbx_validate.cpp).
Status validateInput(const Asset& asset, const WriterOptions& options);

// Object builders, each one job (fbx_geometry.cpp, fbx_skeleton.cpp,
// fbx_morphs.cpp, fbx_animation.cpp).
void buildMeshObjects(SceneContext& ctx);
void buildSkeletonObjects(SceneContext& ctx);
void buildSkinObjects(SceneContext& ctx);
void buildMorphObjects(SceneContext& ctx);
void buildAnimationObjects(SceneContext& ctx);

// An AnimationStack `name` over [start, stop] (KTime) with its one layer;
// returns the layer's id. Keys: `key` + "/stack", "/layer".
int64_t addAnimationLayer(SceneContext& ctx, const std::string& key, const std::string& name,
                          int64_t start, int64_t stop);
// The curves of `clip` on ctx's joints and blend channels, in `layer`, its
// time 0 at `offset` seconds (a scene body's start). Keys under `prefix`.
void addClipCurves(SceneContext& ctx, const AnimationClip& clip, const std::string& prefix,
                   int64_t layer, double offset);
// One curve node (d|X, d|Y, d|Z) of `target`'s vector `property` ("Lcl
// Scaling") keyed at `seconds`; `constant`: keys hold until the next
// (FBX constant interpolation), else linear.
void addPropertyCurves(SceneContext& ctx, const std::string& key, const char* name, int64_t layer,
                       int64_t target, const char* property, const std::vector<double>& seconds,
                       const std::vector<Eigen::Vector3d>& values, bool constant);

// A scene's body i (fbx_scene_bodies.cpp): its node, mesh, skeleton, skin,
// blend shapes, its clip's curves in `layer` from body.start, and its
// visibility as scale keys on its node (`fps`: the scene's source rate).
// `ctx` carries the file built so far.
void buildSceneBody(SceneContext& ctx, const SceneBody& body, size_t i, int64_t layer, double fps);
// The scene's camera (fbx_camera.cpp): a Camera attribute on Model "camera"
// with its transform keyed in `layer`.
void buildSceneCamera(SceneContext& ctx, const SceneCameraClip& camera, int64_t layer);

// Quaternions -> Euler XYZ degrees (R = Rz * Ry * Rx, FBX eEulerXYZ), with
// each frame's angles chosen closest to the previous frame's so curves do
// not jump by 360 or flip between equivalent solutions.
std::vector<Eigen::Vector3d> continuousEulerXYZDegrees(const RotationTrack& q);

}  // namespace fbx
}  // namespace smpl
