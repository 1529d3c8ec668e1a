// composeScene: see scene_timeline.h.
#include "exporter/scene_timeline.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace smpl {
namespace {

// A camera without a field of view is written with this one (60 degrees),
// with a note: glTF requires yfov > 0.
constexpr double kDefaultYfov = M_PI / 3.0;

// Whether `body` is shown on source frame f: inside its clip and detected there.
bool shownAt(const SceneBody& body, const std::vector<bool>& detected, int64_t f) {
  if (f < body.first_frame || f >= body.end_frame) return false;
  const size_t i = size_t(f - body.first_frame);
  return i >= detected.size() || detected[i];
}

// The STEP keys that show `body` on its detected frames of a scene spanning
// [scene_first, scene_end): the value at time 0, then one key half a frame
// before each change. None when it is shown throughout.
void setVisibility(int64_t scene_first, int64_t scene_end, double fps,
                   const std::vector<bool>& detected, SceneBody* body) {
  bool shown = shownAt(*body, detected, scene_first);
  std::vector<double> times = {0.0};
  std::vector<float> values = {shown ? 1.0f : 0.0f};
  for (int64_t f = scene_first + 1; f < scene_end; ++f) {
    if (shownAt(*body, detected, f) == shown) continue;
    shown = !shown;
    times.push_back((double(f - scene_first) - 0.5) / fps);
    values.push_back(shown ? 1.0f : 0.0f);
  }
  if (values.size() == 1 && values[0] == 1.0f) return;  // shown throughout: no channel
  body->visibility_times = std::move(times);
  body->visibility = std::move(values);
}

bool isRotation(const Eigen::Matrix3d& r) {
  return r.allFinite() && (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() < 1e-4 &&
         r.determinant() > 0;
}

// The camera's frames on the timeline from `scene_first`, in the export's world.
Result<SceneCameraClip> cameraClip(const SceneCamera& camera, const Eigen::Matrix3d& turn,
                                   int64_t scene_first, double fps, const std::string& context,
                                   std::vector<std::string>* notes) {
  SceneCameraClip clip;
  if (camera.rotation.size() != camera.position.size())
    return makeError(context + ": the camera has " + std::to_string(camera.rotation.size()) +
                     " rotations for " + std::to_string(camera.position.size()) + " positions");
  // OpenCV camera axes (x right, y down, z forward) from glTF's (x right, y up, looking down -z).
  const Eigen::Matrix3d gltf_to_cv = Eigen::Vector3d(1, -1, -1).asDiagonal();
  Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
  for (size_t f = 0; f < camera.rotation.size(); ++f) {
    if (!isRotation(camera.rotation[f]) || !camera.position[f].allFinite())
      return makeError(context + ": camera frame " + std::to_string(f) +
                       " is not a finite rotation and position");
    Eigen::Quaterniond q(turn * camera.rotation[f] * gltf_to_cv);
    q.normalize();
    if (f > 0 && q.dot(previous) < 0) q.coeffs() *= -1.0;  // the short path between keys
    previous = q;
    clip.times.push_back(double(camera.first_frame + int64_t(f) - scene_first) / fps);
    clip.position.push_back(turn * camera.position[f]);
    clip.rotation.push_back(q.cast<float>());
  }
  clip.aspect = std::isfinite(camera.aspect) && camera.aspect > 0 ? camera.aspect : 0.0;
  clip.yfov = camera.yfov;
  if (!(std::isfinite(clip.yfov) && clip.yfov > 0 && clip.yfov < M_PI)) {
    clip.yfov = kDefaultYfov;
    notes->push_back("the camera has no field of view: written with yfov 60 degrees");
  }
  return clip;
}

}  // namespace

Result<SceneAsset> composeScene(const std::string& name, std::vector<SceneBodyInput> bodies,
                                double fps, const SceneCamera& camera, const Eigen::Matrix3d& turn,
                                const std::string& context) {
  if (bodies.empty()) return makeError(context + ": no track to place in the scene");
  if (!(fps > 0) || !std::isfinite(fps))
    return makeError(context + ": the scene needs a positive frame rate");
  SceneAsset scene;
  scene.name = name;
  scene.fps = fps;
  scene.first_frame = bodies.front().asset.animations.empty()
                          ? 0
                          : bodies.front().asset.animations.front().source.first_frame;
  scene.end_frame = scene.first_frame;
  std::vector<std::vector<bool>> detected;
  for (SceneBodyInput& in : bodies) {
    if (in.asset.animations.size() != 1)
      return makeError(context + ": body '" + in.asset.name + "' has " +
                       std::to_string(in.asset.animations.size()) +
                       " clips (a scene body has one)");
    const ClipSource& source = in.asset.animations.front().source;
    SceneBody body;
    body.track = in.track;
    body.first_frame = source.first_frame;
    body.end_frame = source.end_frame;
    body.asset = std::move(in.asset);
    detected.push_back(std::move(in.detected));
    scene.first_frame = std::min(scene.first_frame, body.first_frame);
    scene.end_frame = std::max(scene.end_frame, body.end_frame);
    scene.bodies.push_back(std::move(body));
  }
  if (camera.present()) {
    scene.first_frame = std::min(scene.first_frame, camera.first_frame);
    scene.end_frame =
        std::max(scene.end_frame, camera.first_frame + int64_t(camera.rotation.size()));
    Result<SceneCameraClip> clip =
        cameraClip(camera, turn, scene.first_frame, fps, context, &scene.notes);
    if (!clip) return clip.error();
    scene.camera = std::move(*clip);
  }
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    SceneBody& body = scene.bodies[i];
    body.start = double(body.first_frame - scene.first_frame) / fps;
    setVisibility(scene.first_frame, scene.end_frame, fps, detected[i], &body);
  }
  return scene;
}

}  // namespace smpl
