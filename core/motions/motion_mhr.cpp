#include "core/motions/motion_mhr.h"

#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

// Keys only SAM 3D Body / MHR outputs carry; any one decides.
const char* const kMhrKeys[] = {"mhr_model_params", "body_pose_params", "hand_pose_params"};

bool isMhrDict(const DataNode& d) {
  if (!d.isDict()) return false;
  for (const char* key : kMhrKeys)
    if (motion_detail::has(d, key)) return true;
  return false;
}

// The dict itself, or a list of per-person dicts (the estimator's return value pickled).
bool matchesMhr(const DataNode& root) {
  if (isMhrDict(root)) return true;
  return root.isList() && !root.children.empty() && isMhrDict(root.children.front());
}

Status refuseMhr(const DataNode&, const LayoutInput& in, MotionSet*) {
  return makeError(in.path +
                   ": MHR parameters (SAM 3D Body), not SMPL: convert them with MHR's "
                   "tools/mhr_smpl_conversion, then export its result (docs/motions.md \"SAM 3D "
                   "Body\")");
}

}  // namespace

const MotionLayout& mhrLayout() {
  static const MotionLayout row{
      "mhr",      "SAM 3D Body / MHR output (refused: convert it to SMPL-X first)", kAnyContainer,
      matchesMhr, {"mhr_model_params", "body_pose_params", "hand_pose_params"},     refuseMhr};
  return row;
}

}  // namespace smpl
