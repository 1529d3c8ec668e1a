#include "core/motions/motion_positions.h"

#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

using motion_detail::has;

bool jointArray(const std::vector<int64_t>& s) {
  return s.size() == 3 && s[0] >= 1 && (s[1] == 22 || s[1] == 21) && s[2] == 3;
}

bool featureArray(const std::vector<int64_t>& s) {
  return s.size() == 2 && s[0] >= 1 && (s[1] == 263 || s[1] == 251);
}

bool mdmResults(const DataNode& root) {
  return root.isDict() && has(root, "motion") && !has(root, "thetas") &&
         (has(root, "lengths") || has(root, "num_samples") || has(root, "num_repetitions"));
}

bool matchesPositions(const DataNode& root) {
  if (root.isArray()) return jointArray(root.array.shape) || featureArray(root.array.shape);
  return mdmResults(root);
}

Status refusePositions(const DataNode& root, const LayoutInput& in, MotionSet*) {
  if (root.isArray() && featureArray(root.array.shape))
    return makeError(in.path +
                     ": HumanML3D motion features: joint positions, no rotations: fit a body "
                     "first, e.g. with SMPLify");
  return makeError(in.path +
                   ": joint positions, no rotations: fit a body first, e.g. with SMPLify (MDM: "
                   "visualize/render_mesh.py writes *_smpl_params.npy)");
}

}  // namespace

const MotionLayout& positionsLayout() {
  static const MotionLayout row{
      "positions",
      "joint positions (MDM results.npy, HumanML3D; refused: no rotations)",
      kNpyFile,
      matchesPositions,
      {"motion", "lengths", "num_samples", "num_repetitions"},
      refusePositions};
  return row;
}

}  // namespace smpl
