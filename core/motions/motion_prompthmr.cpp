#include "core/motions/motion_prompthmr.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "core/io/printable.h"
#include "core/math/libm.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_tracks.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {
using motion_detail::has;

bool isDict(const DataNode* n) { return n && n->isDict(); }

bool matchesPromptHmr(const DataNode& root) {
  const DataNode* people = root.isDict() ? root.get("people") : nullptr;
  if (!isDict(people)) return false;
  if (people->children.empty()) return isDict(root.get("camera_world"));  // refused: no person
  for (const DataNode& person : people->children)
    if (!person.isDict() ||
        (!isDict(person.get("smplx_world")) && !isDict(person.get("smplx_cam"))))
      return false;
  return true;
}

// `pose` of a params dict: (T,165) / (T,55,3) all 55 SMPL-X joints, or
// (T,75) / (T,25,3) root, body, jaw and eyes (smplx_cam: no hands, which then
// stay flat: absolute rotations of a flat_hand_mean=True model).
Status putPose(const DataNode& params, const std::string& ctx, const std::string& group,
               Motion* m) {
  video_rows::Rows rows;
  const std::string key = group + "/pose";
  if (Status s = video_rows::rowsOf(params.get("pose"), ctx, key.c_str(), &rows); !s) return s;
  const Array& a = rows.get();
  const auto& s = a.shape;
  const int64_t width = s.size() == 2 ? s[1] : s.size() == 3 && s[2] == 3 ? 3 * s[1] : 0;
  if (s.empty() || s[0] < 1 || (width != 165 && width != 75))
    return makeError(ctx + ": '" + key + "' has shape " + shapeString(s) +
                     "; expected (T,165) SMPL-X axis-angle (55 joints) or (T,75) (25 joints)");
  m->layout = ModelKind::SmplX;
  if (Status st = motion_detail::allocateFrames(s[0], 55, ctx, m); !st) return st;
  const int joints = static_cast<int>(width / 3);
  for (int64_t f = 0; f < s[0]; ++f)
    motion_detail::putAxisAngle(a.data.data() + f * width, joints, 0, &m->frames[f]);
  if (joints == 25)
    m->notes.push_back("track " + printable(m->track, 64) + ": '" + key +
                       "' has no finger joints (PromptHMR's video model predicts none): the "
                       "hands stay flat");
  return Status();
}

// The per-person keys read; every other one is named in the "ignored" note.
const std::set<std::string>& readKeys() {
  static const std::set<std::string> keys = {"frames", "smplx_world", "smplx_cam"};
  return keys;
}

// One person: the chosen parameters, betas, frame numbers.
Status decodePerson(const DataNode& d, const std::string& id, const LayoutInput& in, Motion* m) {
  const std::string ctx = in.path + ": people " + printable(id, 64);
  const SourceParams want = in.options.source_params;
  const bool world = want != SourceParams::Incam && isDict(d.get("smplx_world"));
  if (want == SourceParams::Global && !world)
    return makeError(ctx + ": --source-params global: no 'smplx_world' for this person");
  const std::string group = world ? "smplx_world" : "smplx_cam";
  const DataNode* params = d.get(group);
  if (!isDict(params))
    return makeError(ctx + ": '" + group + "' is " +
                     (params ? describeNode(*params) : std::string("missing")) +
                     ", expected a dict with pose, shape, trans");
  m->track = id;
  if (Status s = putPose(*params, ctx, group, m); !s) return s;
  video_rows::Rows trans, frames;
  const std::string trans_key = group + "/trans";
  if (Status s = video_rows::rowsOf(params->get("trans"), ctx, trans_key.c_str(), &trans); !s)
    return s;
  if (Status s = video_rows::putTranslation(trans.get(), ctx, trans_key.c_str(), m); !s) return s;
  if (Status s = video_rows::putTrackBetas(*params, "shape", ctx + ": '" + group + "'", m); !s)
    return s;
  if (Status s = video_rows::rowsOf(d.get("frames"), ctx, "frames", &frames); !s) return s;
  Result<std::vector<int64_t>> ids =
      video_rows::frameIds(frames.get(), m->frames.size(), ctx, "frames");
  if (!ids) return ids.error();
  if (world) {
    m->world = MotionWorld::Y;
  } else {
    m->world = MotionWorld::CameraYDown;
    m->world_why = want == SourceParams::Incam
                       ? "PromptHMR's 'smplx_cam' is in the camera frame"
                       : "no 'smplx_world' for this person: PromptHMR's 'smplx_cam' is in the "
                         "camera frame";
  }
  m->fps = 0.0;
  return assembleTrack(*ids, in.path, m);
}

// (N,3,3) and (N,3) arrays of `camera_world`, or an error naming the key.
Result<const Array*> cameraArray(const DataNode& cam, const std::string& path, const char* key,
                                 std::vector<int64_t> tail) {
  const Array* a = cam.leaf(key);
  const std::string name = std::string("'camera_world/") + key + "'";
  if (!a) return makeError(path + ": " + name + " is missing or not an array");
  if (a->shape.size() != tail.size() + 1 || a->shape[0] < 1 ||
      !std::equal(tail.begin(), tail.end(), a->shape.begin() + 1))
    return makeError(path + ": " + name + " has shape " + shapeString(a->shape) + "; expected (N," +
                     (tail.size() == 2 ? "3,3)" : "3)"));
  if (Status s =
          motion_detail::checkNumbers(*a, path, ("camera_world/" + std::string(key)).c_str());
      !s)
    return s.error();
  return a;
}

// One positive number (img_focal) or two (img_center), else 0s.
std::vector<double> scalars(const DataNode& cam, const char* key, size_t n) {
  const Array* a = cam.leaf(key);
  if (!a || a->isString() || a->data.size() != n) return {};
  for (double v : a->data)
    if (!std::isfinite(v) || v <= 0) return {};
  return a->data;
}

// MotionSet::camera from camera_world (scene_camera.h): world-to-camera Rcw,
// Tcw per video frame -> camera-to-world rotation and centre; for incam
// parameters the camera itself (identity at the origin), frame for frame.
Status readCamera(const DataNode& root, const LayoutInput& in, bool world, MotionSet* out) {
  const DataNode* cam = root.get("camera_world");
  if (!isDict(cam)) {
    out->notes.push_back("no 'camera_world' in the file: no scene camera");
    return Status();
  }
  Result<const Array*> rcw = cameraArray(*cam, in.path, "Rcw", {3, 3});
  if (!rcw) return rcw.error();
  Result<const Array*> tcw = cameraArray(*cam, in.path, "Tcw", {3});
  if (!tcw) return tcw.error();
  const int64_t n = (*rcw)->shape[0];
  if ((*tcw)->shape[0] != n)
    return makeError(in.path + ": 'camera_world/Rcw' has " + std::to_string(n) +
                     " frames, 'camera_world/Tcw' " + std::to_string((*tcw)->shape[0]));
  SceneCamera& c = out->camera;
  c.rotation.resize(n);
  c.position.resize(n);
  for (int64_t f = 0; f < n; ++f) {
    const Eigen::Matrix3d r =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>((*rcw)->data.data() + 9 * f);
    const Eigen::Vector3d t = Eigen::Map<const Eigen::Vector3d>((*tcw)->data.data() + 3 * f);
    c.rotation[f] = world ? Eigen::Matrix3d(r.transpose()) : Eigen::Matrix3d::Identity();
    c.position[f] = world ? Eigen::Vector3d(-r.transpose() * t) : Eigen::Vector3d::Zero();
  }
  const std::vector<double> focal = scalars(*cam, "img_focal", 1),
                            centre = scalars(*cam, "img_center", 2);
  if (!focal.empty() && !centre.empty()) {
    c.yfov = 2.0 * libm::atan(centre[1] / focal[0]);
    c.aspect = centre[0] / centre[1];
  }
  out->notes.push_back(world ? "scene camera from 'camera_world' (Rcw, Tcw; " + std::to_string(n) +
                                   " frames)"
                             : "scene camera: the camera frame itself ('smplx_cam'; " +
                                   std::to_string(n) + " frames of 'camera_world')");
  return Status();
}

// "ignored: camera, masks, ...; per person: bboxes, ..." for the keys no track reads.
void noteIgnored(const DataNode& root, const DataNode& people, MotionSet* out) {
  std::string top;
  for (const std::string& key : root.keys)
    if (key != "people" && key != "camera_world")
      top += (top.empty() ? "" : ", ") + printable(key, 64);
  std::set<std::string> ignored;
  for (const DataNode& person : people.children) {
    for (const std::string& key : person.keys)
      if (!readKeys().count(key)) ignored.insert(printable(key, 64));
    if (const DataNode* cam = person.get("smplx_cam"); isDict(cam))
      for (const std::string& key : cam->keys)
        if (key != "pose" && key != "shape" && key != "trans")
          ignored.insert("smplx_cam/" + printable(key, 64));
  }
  std::string list;
  for (const std::string& key : ignored) list += (list.empty() ? "" : ", ") + key;
  if (!top.empty() || !list.empty())
    out->notes.push_back("ignored: " + (top.empty() ? std::string("-") : top) +
                         "; per person: " + (list.empty() ? std::string("-") : list) +
                         " (the SLAM camera before gravity alignment, detections, image features, "
                         "the image model's estimates; the video model's parameters are read)");
}

Status decodePromptHmr(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  const DataNode& people = *root.get("people");
  if (people.children.empty())
    return makeError(in.path + ": PromptHMR results with no tracked person ('people' is empty)");
  out->notes.push_back("read as PromptHMR output (people by track id; SMPL-X)");
  bool any_world = false;
  for (size_t i = 0; i < people.children.size(); ++i) {
    Motion m;
    if (Status s = decodePerson(people.children[i], people.keys[i], in, &m); !s) return s;
    any_world |= m.world == MotionWorld::Y;
    out->tracks.push_back(std::move(m));
  }
  if (any_world) {
    out->notes.push_back(
        "world frame ('smplx_world'; PromptHMR's gravity-aligned world: Y up, floor at y = 0)");
    out->notes.push_back(
        "hands: absolute finger rotations of 'pose' (PromptHMR's SMPL-X: flat_hand_mean=True)");
  }
  noteIgnored(root, people, out);
  return readCamera(root, in, any_world, out);
}

}  // namespace

const MotionLayout& promptHmrLayout() {
  static const MotionLayout row{"prompthmr",
                                "PromptHMR results.pkl (people with smplx_world / smplx_cam)",
                                kJoblibFile | kPickleFile,
                                matchesPromptHmr,
                                {"people", "camera_world"},
                                decodePromptHmr};
  return row;
}

}  // namespace smpl
