#include "core/motions/motion_phalp.h"

#include <map>
#include <utility>

#include "core/io/printable.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_tracks.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {
using motion_detail::has;

bool matchesPhalp(const DataNode& root) {
  if (!root.isDict() || root.children.empty()) return false;
  for (const DataNode& frame : root.children)
    if (!frame.isDict() || !has(frame, "tid") || !has(frame, "tracked_time") || !has(frame, "smpl"))
      return false;
  return true;
}

// One track's detections, in file order.
struct Detections {
  std::vector<int64_t> frames;
  std::vector<Eigen::Matrix3d> root;
  std::vector<Rotations> body;
  std::vector<Eigen::Vector3d> camera;
  std::vector<double> betas;  // rows of 10
  int64_t betas_width = -1;
  MemoryCharge charge;  // the rows above, charged before each detection is kept
};

// A numeric leaf of `node`'s child `key` with exactly `n` values, else an error.
Result<const Array*> valuesOf(const DataNode& node, const char* key, int64_t n,
                              const std::string& ctx, const std::string& expected) {
  const Array* a = node.leaf(key);
  if (!a || a->isString() || a->size() != n || static_cast<int64_t>(a->data.size()) != n)
    return makeError(ctx + ": '" + key + "' is " +
                     (node.get(key) ? describeNode(*node.get(key)) : std::string("missing")) +
                     "; expected " + expected);
  if (Status s = motion_detail::checkNumbers(*a, ctx, key); !s) return s.error();
  return a;
}

// Entry i of a frame: its smpl parameters and camera translation.
Status readDetection(const DataNode& frame, size_t i, const std::string& ctx, Detections* d) {
  const DataNode* smpl = frame.get("smpl");
  if (!smpl || !smpl->isList() || i >= smpl->children.size() || !smpl->children[i].isDict())
    return makeError(ctx + ": 'smpl' has no parameter dict for this entry");
  const DataNode& p = smpl->children[i];
  const uint64_t bytes = sizeof(Rotations) + 25 * sizeof(Eigen::Matrix3d) + 16 * sizeof(double);
  if (Status s = d->charge.add(bytes, ctx, "a detection"); !s) return s;
  Result<const Array*> go = valuesOf(p, "global_orient", 9, ctx + " smpl", "(1,3,3) rotation");
  if (!go) return go.error();
  Result<const Array*> bp =
      valuesOf(p, "body_pose", 207, ctx + " smpl", "(23,3,3) rotation matrices");
  if (!bp) return bp.error();
  Rotations root(1), body(24, Eigen::Matrix3d::Identity());
  motion_detail::putMatrices((*go)->data.data(), 1, 0, &root);
  motion_detail::putMatrices((*bp)->data.data(), 23, 1, &body);
  d->root.push_back(root[0]);
  d->body.push_back(std::move(body));
  if (const Array* b = p.leaf("betas")) {
    if (Status s = motion_detail::checkNumbers(*b, ctx + " smpl", "betas"); !s) return s;
    if (d->betas_width >= 0 && b->size() != d->betas_width)
      return makeError(ctx + ": 'betas' has " + std::to_string(b->size()) + " values; earlier " +
                       std::to_string(d->betas_width));
    d->betas_width = b->size();
    d->betas.insert(d->betas.end(), b->data.begin(), b->data.end());
  }
  Array scratch;
  Result<const Array*> element = video_rows::elementOf(frame.get("camera"), i, ctx, &scratch);
  if (!element) return element.error();
  const Array* cam = *element;
  if (!cam || cam->size() != 3 || cam->data.size() != 3)
    return makeError(ctx + ": 'camera' has no (3,) translation for this entry");
  if (Status s = motion_detail::checkNumbers(*cam, ctx, "camera"); !s) return s;
  d->camera.push_back(Eigen::Map<const Eigen::Vector3d>(cam->data.data()));
  return Status();
}

// Every detection of the frame (tracked_time == 0) into its track.
Status readFrame(const DataNode& frame, const std::string& name, const std::string& path,
                 std::map<std::string, Detections>* tracks) {
  const std::string ctx = path + ": frame '" + printable(name, 64) + "'";
  Result<const Array*> time = valuesOf(frame, "time", 1, ctx, "an integer frame index");
  if (!time) return time.error();
  Result<std::string> t = video_rows::idText((*time)->data[0], ctx, "time");
  if (!t) return t.error();
  const DataNode* tid = frame.get("tid");
  const DataNode* since = frame.get("tracked_time");
  const size_t n = video_rows::countOf(tid);
  if (video_rows::countOf(since) != n)
    return makeError(ctx + ": 'tracked_time' has " + std::to_string(video_rows::countOf(since)) +
                     " entries for " + std::to_string(n) + " in 'tid'");
  for (size_t i = 0; i < n; ++i) {
    Array a, b;
    Result<const Array*> id = video_rows::elementOf(tid, i, ctx, &a);
    Result<const Array*> late = video_rows::elementOf(since, i, ctx, &b);
    if (!id) return id.error();
    if (!late) return late.error();
    if (!*id || (*id)->data.size() != 1 || !*late || (*late)->data.size() != 1)
      return makeError(ctx + ": 'tid' / 'tracked_time' entry " + std::to_string(i) +
                       " is not a number");
    if ((*late)->data[0] != 0) continue;  // not detected here: holds its last detection
    Result<std::string> key = video_rows::idText((*id)->data[0], ctx, "tid");
    if (!key) return key.error();
    Detections& d = (*tracks)[*key];
    if (Status s = readDetection(frame, i, ctx + " track " + *key, &d); !s) return s;
    d.frames.push_back(std::stoll(*t));
  }
  return Status();
}

Status toMotion(const std::string& id, Detections& d, const std::string& path, Motion* m) {
  m->track = id;
  m->layout = ModelKind::Smpl;
  if (Status s = motion_detail::allocateFrames(static_cast<int64_t>(d.frames.size()), 24, path, m);
      !s)
    return s;
  for (size_t f = 0; f < d.frames.size(); ++f) {
    m->frames[f] = std::move(d.body[f]);
    m->frames[f][0] = d.root[f];
  }
  m->translation = d.camera;
  if (d.betas_width > 0) {
    Array rows;
    rows.shape = {static_cast<int64_t>(d.frames.size()), d.betas_width};
    rows.data = std::move(d.betas);
    rows.dtype = "<f8";
    if (Status s = video_rows::putBetas(rows, path, "betas", "track " + id + ": ", m); !s) return s;
  }
  m->world = MotionWorld::CameraYDown;
  m->world_why = "PHALP's 'smpl' and 'camera' are in the camera frame";
  m->fps = 0.0;
  return assembleTrack(d.frames, path, m);
}

Status decodePhalp(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  if (in.options.source_params == SourceParams::Global)
    return makeError(in.path +
                     ": --source-params global: PHALP output has no world-frame parameters");
  std::map<std::string, Detections> tracks;
  for (size_t i = 0; i < root.children.size(); ++i)
    if (Status s = readFrame(root.children[i], root.keys[i], in.path, &tracks); !s) return s;
  if (tracks.empty())
    return makeError(in.path + ": no tracked person (no frame lists a 'tracked_ids' entry)");
  out->notes.push_back("read as PHALP output (4D-Humans; tracks by 'tid'; SMPL)");
  out->notes.push_back(
      "'camera' (the predicted camera translation, focal length 5000 px) is the translation");
  for (auto& [id, d] : tracks) {
    Motion m;
    if (Status s = toMotion(id, d, in.path, &m); !s) return s;
    out->tracks.push_back(std::move(m));
  }
  return Status();
}

}  // namespace

const MotionLayout& phalpLayout() {
  static const MotionLayout row{"phalp",
                                "PHALP / 4D-Humans output (per-frame tid, tracked_time, smpl)",
                                kJoblibFile | kPickleFile,
                                matchesPhalp,
                                {"time", "tid", "tracked_time", "tracked_ids", "smpl", "camera"},
                                decodePhalp};
  return row;
}

}  // namespace smpl
