#include "request/request_motions.h"

#include <atomic>
#include <filesystem>

#include "core/io/name_component.h"
#include "core/motions/motion_fit.h"
#include "core/motions/motion_layout.h"
#include "core/motions/motion_sequence.h"
#include "core/os/path.h"

namespace smpl {
namespace {

std::atomic<uint64_t> decoded{0};

MotionOptions motionOptionsOf(const ExportRequest& r) {
  MotionOptions options = r.reading;
  options.up_given = r.animation.up != UpAxis::Auto;  // no note about the layout's default turn
  return options;
}

}  // namespace

Result<MotionSet> decodeMotionSet(const std::string& path, const ExportRequest& r) {
  ++decoded;
  if (!r.motion_sequence.empty() && path == r.motion_sequence)
    return loadMotionSequence(path, motionOptionsOf(r));
  std::error_code ec;
  if (std::filesystem::is_directory(os::fsPath(path), ec))
    return makeError(path +
                     ": a folder: give --motion-sequence DIR for per-frame files of one motion, or "
                     "--motion-dir DIR --out-dir OUT to convert every motion in it");
  return loadMotionSet(path, motionOptionsOf(r));
}

Result<Motion> decodeMotion(const std::string& path, const ExportRequest& r) {
  Result<MotionSet> set = decodeMotionSet(path, r);
  if (!set) return set.error();
  TrackChoice choice = r.track;
  if (choice.kind == TrackChoice::Kind::All) choice.kind = TrackChoice::Kind::Longest;
  Result<std::vector<Motion>> picked = selectTracks(std::move(*set), choice, path);
  if (!picked) return picked.error();
  return std::move(picked->front());
}

Result<Motion> decodeMotionTree(DataNode root, const std::string& name, const ExportRequest& r) {
  ++decoded;
  bool flat = root.isDict();  // np.savez of it: an .npz
  for (const DataNode& child : root.children) flat = flat && child.isArray();
  const unsigned containers = flat ? kNpzFile : kAnyContainer & ~kNpzFile;
  Result<MotionSet> set =
      loadMotionSetFromTree(std::move(root), containers, name, motionOptionsOf(r));
  if (!set) return set.error();
  TrackChoice choice = r.track;
  if (choice.kind == TrackChoice::Kind::All) choice.kind = TrackChoice::Kind::Longest;
  Result<std::vector<Motion>> picked = selectTracks(std::move(*set), choice, name);
  if (!picked) return picked.error();
  return std::move(picked->front());
}

Status resolveMotionHands(const BodyModel& model, const ExportRequest& request,
                          const std::string& path, Motion* motion) {
  return resolveFitHands(model, request.flat_hand_mean, path, motion);
}

std::string trackOutput(const std::string& out, const std::string& id) {
  const std::string name = os::utf8(os::fsPath(out).filename());
  const size_t dot = name.rfind('.');
  const size_t cut = out.size() - name.size() + (dot == std::string::npos ? name.size() : dot);
  return out.substr(0, cut) + ".track" + safeNameComponent(id) + out.substr(cut);
}

uint64_t motionsDecoded() { return decoded.load(); }

}  // namespace smpl
