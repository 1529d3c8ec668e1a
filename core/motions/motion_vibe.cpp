#include "core/motions/motion_vibe.h"

#include <utility>

#include "core/io/printable.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_tracks.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {
using motion_detail::has;

bool matchesVibe(const DataNode& root) {
  if (!root.isDict() || root.children.empty()) return false;
  for (const DataNode& person : root.children)
    if (!person.isDict() || !has(person, "pose") || !has(person, "frame_ids") ||
        !has(person, "orig_cam") || has(person, "trans"))
      return false;
  return true;
}

Status decodePerson(const DataNode& d, const std::string& id, const LayoutInput& in, Motion* m) {
  const std::string ctx = in.path + ": track " + printable(id, 64);
  m->track = id;
  video_rows::Rows pose, frames;
  if (Status s = video_rows::rowsOf(d.get("pose"), ctx, "pose", &pose); !s) return s;
  if (Status s = video_rows::putSmplPoses(pose.get(), ctx, "pose", m); !s) return s;
  if (Status s = video_rows::putTrackBetas(d, "betas", ctx, m); !s) return s;
  if (Status s = video_rows::rowsOf(d.get("frame_ids"), ctx, "frame_ids", &frames); !s) return s;
  Result<std::vector<int64_t>> ids =
      video_rows::frameIds(frames.get(), m->frames.size(), ctx, "frame_ids");
  if (!ids) return ids.error();
  m->world = MotionWorld::CameraYDown;
  m->world_why = "VIBE's 'pose' is in the camera frame";
  m->fps = 0.0;
  return assembleTrack(*ids, in.path, m);
}

Status decodeVibe(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  if (in.options.source_params == SourceParams::Global)
    return makeError(in.path +
                     ": --source-params global: VIBE output has no world-frame parameters");
  out->notes.push_back("read as VIBE output (persons by id; SMPL)");
  out->notes.push_back(
      "no 3-D translation is stored (pred_cam/orig_cam are weak-perspective image cameras): the "
      "translation is zero");
  for (size_t i = 0; i < root.children.size(); ++i) {
    Motion m;
    if (Status s = decodePerson(root.children[i], root.keys[i], in, &m); !s) return s;
    out->tracks.push_back(std::move(m));
  }
  return Status();
}

}  // namespace

const MotionLayout& vibeLayout() {
  static const MotionLayout row{"vibe",
                                "VIBE output (per-person pose, betas, orig_cam, frame_ids)",
                                kJoblibFile | kPickleFile,
                                matchesVibe,
                                {"pose", "betas", "frame_ids", "orig_cam"},
                                decodeVibe};
  return row;
}

}  // namespace smpl
