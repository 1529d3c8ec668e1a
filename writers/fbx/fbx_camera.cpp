// The camera of a --scene FBX (fbx_scene_internal.h buildSceneCamera): a
// Camera NodeAttribute on Model "camera", its Lcl Translation and Lcl
// Rotation keyed at the clip's times (linear), its field of view fixed.
#include <Eigen/Geometry>
#include <cmath>

#include "core/math/libm.h"
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMillimetresPerInch = 25.4;
// Film height (mm, the 35 mm still frame's): FBX derives the field of view
// from the focal length and the film gate (ApertureMode focal length), as
// Blender's importer does (lens, sensor size), so the gate is arbitrary.
constexpr double kFilmHeightMm = 24.0;
// Clipping planes (metres), as the glTF scene camera's.
constexpr double kNearMetres = 0.01;
constexpr double kFarMetres = 1000.0;

// An FBX camera looks down its node's +X with +Y up (Blender's io_scene_fbx
// fbx_utils.py MAT_CONVERT_CAMERA: "Blender is -Z, FBX is +X"); the clip's
// rotation is a glTF camera's (looking down -Z, +Y up). The node's rotation
// is the clip's times Ry(+90 degrees), which takes +X to -Z and keeps +Y.
Eigen::Quaternionf fbxCameraRotation(const Eigen::Quaternionf& gltf) {
  const double h = std::sqrt(0.5);  // cos and sin of 45 degrees: Ry(+90) as (w, x, y, z)
  const Eigen::Quaterniond turn(h, 0, h, 0);
  return (gltf.cast<double>() * turn).normalized().cast<float>();
}

void addCameraAttribute(SceneContext& ctx, const SceneCameraClip& c, int64_t model) {
  const double aspect = c.aspect > 0 ? c.aspect : 1.0;  // unknown: a square gate
  const double tan_half_y = libm::tan(c.yfov / 2);
  const double focal_mm = kFilmHeightMm / 2 / tan_half_y;
  const double xfov = 2 * libm::atan(aspect * tan_half_y);
  int64_t attr = ctx.ids.id("camera/attribute");
  FbxNode& a = ctx.addObject("NodeAttribute", attr, "camera", "NodeAttribute", "Camera");
  FbxNode& p = a.add("Properties70");
  pDouble(p, "FilmWidth", kFilmHeightMm * aspect / kMillimetresPerInch);  // inches
  pDouble(p, "FilmHeight", kFilmHeightMm / kMillimetresPerInch);
  pDouble(p, "FilmAspectRatio", aspect);
  pEnum(p, "ApertureMode", 3);  // focal length: the view from FocalLength and the film
  pEnum(p, "GateFit", 1);       // vertical: the film height holds yfov
  addP(p, "FieldOfView", "FieldOfView", "", "A").addDouble(xfov * 180 / kPi);  // as Blender writes
  addP(p, "FieldOfViewX", "FieldOfViewX", "", "A").addDouble(xfov * 180 / kPi);
  addP(p, "FieldOfViewY", "FieldOfViewY", "", "A").addDouble(c.yfov * 180 / kPi);
  addP(p, "FocalLength", "Number", "", "A").addDouble(focal_mm);
  pDouble(p, "NearPlane", kNearMetres * ctx.scale);
  pDouble(p, "FarPlane", kFarMetres * ctx.scale);
  a.add("TypeFlags").addString("Camera");
  a.add("GeometryVersion").addInt32(124);
  ctx.connectOO(attr, model);
}

}  // namespace

void buildSceneCamera(SceneContext& ctx, const SceneCameraClip& c, int64_t layer) {
  RotationTrack rotation(c.rotation.size());
  std::vector<Eigen::Vector3d> position(c.position.size());
  for (size_t f = 0; f < rotation.size(); ++f) rotation[f] = fbxCameraRotation(c.rotation[f]);
  for (size_t f = 0; f < position.size(); ++f) position[f] = c.position[f] * ctx.scale;
  std::vector<Eigen::Vector3d> euler = continuousEulerXYZDegrees(rotation);

  int64_t model = ctx.ids.id("camera/model");
  FbxNode& m = ctx.addObject("Model", model, "camera", "Model", "Camera");
  addModelBody(m, position[0], euler[0]);  // the first key, for readers without animation
  ctx.connectOO(model, 0);
  addCameraAttribute(ctx, c, model);
  addPropertyCurves(ctx, "camera/T", "T", layer, model, "Lcl Translation", c.times, position,
                    false);
  addPropertyCurves(ctx, "camera/R", "R", layer, model, "Lcl Rotation", c.times, euler, false);
}

}  // namespace fbx
}  // namespace smpl
