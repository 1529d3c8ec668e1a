#include "core/motions/motion_wham.h"

#include <utility>

#include "core/io/printable.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_tracks.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {
using motion_detail::has;

bool matchesWham(const DataNode& root) {
  if (!root.isDict() || root.children.empty()) return false;
  for (const DataNode& track : root.children)
    if (!track.isDict() || !has(track, "pose") || !has(track, "frame_ids") || !has(track, "trans"))
      return false;
  return true;
}

// One track: world or camera parameters, betas, frame numbers.
Status decodeTrack(const DataNode& d, const std::string& id, const LayoutInput& in, Motion* m) {
  const std::string ctx = in.path + ": track " + printable(id, 64);
  const SourceParams want = in.options.source_params;
  bool world = want != SourceParams::Incam && has(d, "pose_world");
  if (want == SourceParams::Global && !world)
    return makeError(ctx + ": --source-params global: no 'pose_world' in this WHAM track");
  m->track = id;
  video_rows::Rows pose, trans, frames;
  if (Status s = video_rows::rowsOf(d.get(world ? "pose_world" : "pose"), ctx,
                                    world ? "pose_world" : "pose", &pose);
      !s)
    return s;
  if (Status s = video_rows::putSmplPoses(pose.get(), ctx, world ? "pose_world" : "pose", m); !s)
    return s;
  const char* trans_key = world ? "trans_world" : "trans";
  if (Status s = video_rows::rowsOf(d.get(trans_key), ctx, trans_key, &trans); !s) return s;
  if (Status s = video_rows::putTranslation(trans.get(), ctx, trans_key, m); !s) return s;
  if (Status s = video_rows::putTrackBetas(d, "betas", ctx, m); !s) return s;
  if (Status s = video_rows::rowsOf(d.get("frame_ids"), ctx, "frame_ids", &frames); !s) return s;
  Result<std::vector<int64_t>> ids =
      video_rows::frameIds(frames.get(), m->frames.size(), ctx, "frame_ids");
  if (!ids) return ids.error();
  if (world) {
    m->world = MotionWorld::Y;
    m->notes.push_back("world frame ('pose_world', 'trans_world'; Y up)");
  } else {
    m->world = MotionWorld::CameraYDown;
    m->world_why = want == SourceParams::Incam
                       ? "WHAM's 'pose' and 'trans' are in the camera frame"
                       : "no 'pose_world' in the track: WHAM's 'pose' and 'trans' are in the "
                         "camera frame";
  }
  m->fps = 0.0;
  return assembleTrack(*ids, in.path, m);
}

Status decodeWham(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  out->notes.push_back("read as WHAM output (tracks by id; SMPL)");
  for (size_t i = 0; i < root.children.size(); ++i) {
    Motion m;
    if (Status s = decodeTrack(root.children[i], root.keys[i], in, &m); !s) return s;
    out->tracks.push_back(std::move(m));
  }
  return Status();
}

}  // namespace

const MotionLayout& whamLayout() {
  static const MotionLayout row{
      "wham",
      "WHAM output (per-track pose, trans, pose_world, frame_ids)",
      kJoblibFile | kPickleFile,
      matchesWham,
      {"pose", "trans", "pose_world", "trans_world", "betas", "frame_ids"},
      decodeWham};
  return row;
}

}  // namespace smpl
