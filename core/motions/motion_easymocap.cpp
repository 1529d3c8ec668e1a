#include "core/motions/motion_easymocap.h"

#include <string>
#include <unordered_set>
#include <utility>

#include "core/io/file_io.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_sequence.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {
using motion_detail::has;

bool matchesEasymocap(const DataNode& root) {
  if (!root.isList() || root.children.empty()) return false;
  for (const DataNode& person : root.children)
    if (!person.isDict() || !has(person, "Rh") || !has(person, "Th") || !has(person, "poses"))
      return false;
  return true;
}

// `key` of one person: exactly `n` numbers (one row), else an error.
Result<const Array*> values(const DataNode& person, const char* key, int64_t n,
                            const std::string& ctx) {
  const Array* a = person.leaf(key);
  if (!a || a->isString() || a->size() != n || static_cast<int64_t>(a->data.size()) != n)
    return makeError(ctx + ": '" + key + "' is " +
                     (person.get(key) ? describeNode(*person.get(key)) : std::string("missing")) +
                     "; expected (1," + std::to_string(n) + ")");
  if (Status s = motion_detail::checkNumbers(*a, ctx, key); !s) return s.error();
  return a;
}

// SMPL-H / SMPL-X parameters (hands as PCA, expression) are not read.
Status refuseHandsAndFace(const DataNode& person, const std::string& path) {
  std::string keys;
  for (const char* key : {"handl", "handr", "expression"})
    if (has(person, key)) keys += std::string(keys.empty() ? "" : ", ") + "'" + key + "'";
  const Array* poses = person.leaf("poses");
  if (keys.empty() && poses && (poses->size() == 78 || poses->size() == 87))
    keys = "'poses' of " + std::to_string(poses->size()) + " values";
  if (keys.empty()) return Status();
  return makeError(path + ": EasyMocap SMPL-H/SMPL-X parameters (" + keys + ") are not read");
}

Status decodePerson(const DataNode& person, size_t index, const LayoutInput& in, Motion* m) {
  const std::string ctx = in.path + ": person " + std::to_string(index);
  if (!person.isDict()) return makeError(ctx + ": " + describeNode(person) + ", expected a dict");
  if (Status s = refuseHandsAndFace(person, in.path); !s) return s;
  Result<const Array*> id = values(person, "id", 1, ctx);
  if (!id) return id.error();
  Result<std::string> track = video_rows::idText((*id)->data[0], ctx, "id");
  if (!track) return track.error();
  Result<const Array*> poses = values(person, "poses", 72, ctx);
  if (!poses) return poses.error();
  Result<const Array*> rh = values(person, "Rh", 3, ctx);
  if (!rh) return rh.error();
  Result<const Array*> th = values(person, "Th", 3, ctx);
  if (!th) return th.error();
  m->track = *track;
  m->layout = ModelKind::Smpl;
  if (Status s = motion_detail::allocateFrames(1, 24, in.path, m); !s) return s;
  motion_detail::putAxisAngle((*poses)->data.data(), 24, 0, &m->frames[0]);
  m->translation.assign(1, Eigen::Vector3d::Zero());
  Rotations turn(1);
  motion_detail::putAxisAngle((*rh)->data.data(), 1, 0, &turn);
  m->world_rotation = {turn[0]};
  m->world_translation = {Eigen::Map<const Eigen::Vector3d>((*th)->data.data())};
  if (const Array* shapes = person.leaf("shapes")) {
    if (Status s = motion_detail::checkNumbers(*shapes, ctx, "shapes"); !s) return s;
    m->betas = shapes->data;
  }
  m->world = MotionWorld::Z;
  m->fps = 0.0;
  // Alone, the file's name gives its frame; in a sequence the sequence numbers it.
  int64_t frame = 0;
  std::string suffix;
  if (!in.options.frame_file && parseFrameName(baseName(in.path), &frame, &suffix))
    m->first_frame = frame;
  return Status();
}

Status decodeEasymocap(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  if (in.options.source_params == SourceParams::Incam)
    return makeError(in.path +
                     ": --source-params incam: EasyMocap output has no camera-frame parameters");
  out->notes.push_back("read as EasyMocap output (persons by id; SMPL; Rh/Th about the origin)");
  out->notes.push_back("world frame of the calibration (Z up; --up z)");
  std::unordered_set<std::string> ids;  // a set, not a scan per person: linear in persons
  out->tracks.reserve(root.children.size());
  for (size_t i = 0; i < root.children.size(); ++i) {
    Motion m;
    if (Status s = decodePerson(root.children[i], i, in, &m); !s) return s;
    if (!ids.insert(m.track).second)
      return makeError(in.path + ": two persons with id " + m.track + " in one frame");
    out->tracks.push_back(std::move(m));
  }
  return Status();
}

}  // namespace

const MotionLayout& easymocapLayout() {
  static const MotionLayout row{"easymocap",
                                "EasyMocap SMPL JSON (a list of persons with Rh, Th, poses)",
                                kJsonFile,
                                matchesEasymocap,
                                {"id", "Rh", "Th", "poses", "shapes"},
                                decodeEasymocap};
  return row;
}

}  // namespace smpl
