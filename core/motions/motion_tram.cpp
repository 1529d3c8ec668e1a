#include "core/motions/motion_tram.h"

#include <filesystem>
#include <utility>

#include "core/io/tree/data_tree.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_tracks.h"
#include "core/motions/motion_video_rows.h"
#include "core/os/path.h"

namespace smpl {
namespace {
using motion_detail::has;

bool matchesTram(const DataNode& root) {
  return root.isDict() && has(root, "pred_rotmat") && has(root, "pred_trans") && has(root, "frame");
}

// <dir of the track>/../camera.npy (TRAM's seq folder: hps/hps_track_<k>.npy).
std::string cameraPath(const std::string& track_path) {
  namespace fs = std::filesystem;
  return os::utf8(os::fsPath(track_path).parent_path().parent_path() / "camera.npy");
}

// Camera-to-world per row from camera.npy's world_cam_R/T at the rows' frames.
Status readWorld(const std::string& camera, const std::vector<int64_t>& frames,
                 const std::string& path, Motion* m) {
  Result<DataNode> cam = readDataTree(camera);
  if (!cam) return cam.error();
  const Array* r = cam->leaf("world_cam_R");
  const Array* t = cam->leaf("world_cam_T");
  if (!r || !t || r->isString() || t->isString() || r->shape.size() != 3 || r->shape[1] != 3 ||
      r->shape[2] != 3 || t->shape.size() != 2 || t->shape[1] != 3 || t->shape[0] != r->shape[0])
    return makeError(camera +
                     ": expected 'world_cam_R' (N,3,3) and 'world_cam_T' (N,3) (TRAM's "
                     "camera.npy)");
  if (Status s = motion_detail::checkNumbers(*r, camera, "world_cam_R"); !s) return s;
  if (Status s = motion_detail::checkNumbers(*t, camera, "world_cam_T"); !s) return s;
  const int64_t n = r->shape[0];
  Rotations one(1);
  for (int64_t f : frames) {
    if (f >= n)
      return makeError(path + ": frame " + std::to_string(f) + " is beyond the " +
                       std::to_string(n) + " cameras of " + camera);
    motion_detail::putMatrices(r->data.data() + 9 * f, 1, 0, &one);
    m->world_rotation.push_back(one[0]);
    m->world_translation.push_back(Eigen::Map<const Eigen::Vector3d>(t->data.data() + 3 * f));
  }
  return Status();
}

Status decodeTram(const DataNode& d, const LayoutInput& in, MotionSet* out) {
  Motion m;
  video_rows::Rows rot, trans, shape, frame;
  if (Status s = video_rows::rowsOf(d.get("pred_rotmat"), in.path, "pred_rotmat", &rot); !s)
    return s;
  if (rot.get().shape.size() != 4)
    return makeError(in.path + ": 'pred_rotmat' has shape " + shapeString(rot.get().shape) +
                     "; expected (T,24,3,3)");
  if (Status s = video_rows::putSmplPoses(rot.get(), in.path, "pred_rotmat", &m); !s) return s;
  if (Status s = video_rows::rowsOf(d.get("pred_trans"), in.path, "pred_trans", &trans); !s)
    return s;
  if (Status s = video_rows::putTranslation(trans.get(), in.path, "pred_trans", &m); !s) return s;
  if (has(d, "pred_shape")) {
    if (Status s = video_rows::rowsOf(d.get("pred_shape"), in.path, "pred_shape", &shape); !s)
      return s;
    if (Status s = video_rows::putBetas(shape.get(), in.path, "pred_shape", "", &m); !s) return s;
  }
  if (Status s = video_rows::rowsOf(d.get("frame"), in.path, "frame", &frame); !s) return s;
  Result<std::vector<int64_t>> frames =
      video_rows::frameIds(frame.get(), m.frames.size(), in.path, "frame");
  if (!frames) return frames.error();
  const std::string camera = cameraPath(in.path);
  std::error_code ec;
  const bool beside = std::filesystem::is_regular_file(os::fsPath(camera), ec);
  const SourceParams want = in.options.source_params;
  if (want == SourceParams::Global && !beside)
    return makeError(in.path + ": --source-params global: no camera.npy beside the track (" +
                     camera + ")");
  m.notes.push_back("read as TRAM output (SMPL; one person per file)");
  if (beside && want != SourceParams::Incam) {
    if (Status s = readWorld(camera, *frames, in.path, &m); !s) return s;
    m.world = MotionWorld::Y;
    m.notes.push_back("world frame (camera.npy world_cam_R/T; Y up)");
  } else {
    m.world = MotionWorld::CameraYDown;
    m.world_why = beside ? "TRAM's 'pred_rotmat' and 'pred_trans' are in the camera frame"
                         : "no camera.npy beside the track (" + camera +
                               "): TRAM's 'pred_rotmat' and 'pred_trans' are in the camera frame";
  }
  m.fps = 0.0;
  if (Status s = assembleTrack(*frames, in.path, &m); !s) return s;
  out->tracks.push_back(std::move(m));
  return Status();
}

}  // namespace

const MotionLayout& tramLayout() {
  static const MotionLayout row{"tram",
                                "TRAM hps_track_<k>.npy (pred_rotmat, pred_trans, frame)",
                                kNpyFile | kPickleFile,
                                matchesTram,
                                {"pred_rotmat", "pred_trans", "pred_shape", "frame"},
                                decodeTram};
  return row;
}

}  // namespace smpl
