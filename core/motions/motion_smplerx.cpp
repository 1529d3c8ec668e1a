#include "core/motions/motion_smplerx.h"

#include <algorithm>
#include <utility>

#include "core/motions/motion_fit.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

const std::vector<std::string>& smplerxKeys() {
  static const std::vector<std::string> keys = {
      "global_orient", "body_pose", "left_hand_pose", "right_hand_pose", "jaw_pose",
      "leye_pose",     "reye_pose", "betas",          "expression",      "transl"};
  return keys;
}

// Exactly SMPLer-X's ten keys (a fit with any other key stays the fit row's).
bool matchesSmplerx(const DataNode& root) {
  if (!root.isDict() || root.keys.size() != smplerxKeys().size()) return false;
  for (const std::string& key : smplerxKeys())
    if (std::find(root.keys.begin(), root.keys.end(), key) == root.keys.end()) return false;
  return true;
}

Status decodeSmplerx(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  if (in.options.frame_file && in.options.source_params == SourceParams::Global)
    return makeError(in.path +
                     ": --source-params global: SMPLer-X output has no world-frame parameters");
  Motion m;
  if (Status s = motion_detail::decodeFit(root, in.path, &m); !s) return s;
  if (!in.options.frame_file) {
    m.source_layout = "fit";  // alone: today's fit (Y up), see the header
  } else {
    m.notes.push_back("read as SMPLer-X output (one file per frame and detection; SMPL-X)");
    m.notes.push_back(
        "the file suffix _<i> is a detection index per frame, not a tracked identity");
    m.world = MotionWorld::CameraYDown;
    m.world_why = "SMPLer-X's 'transl' is in the camera frame";
  }
  out->tracks.push_back(std::move(m));
  return Status();
}

}  // namespace

const MotionLayout& smplerxLayout() {
  static const MotionLayout row{
      "smplerx",     "SMPLer-X per-frame SMPL-X parameters (--motion-sequence)",
      kNpzFile,      matchesSmplerx,
      smplerxKeys(), decodeSmplerx};
  return row;
}

}  // namespace smpl
