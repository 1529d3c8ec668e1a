#include "core/motions/motion_bare_poses.h"

#include <algorithm>
#include <cmath>

#include "core/motions/motion_amass.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

bool familyJoints(int64_t k) { return k == 24 || k == 52 || k == 55 || k == 16; }

bool barePoseShape(const std::vector<int64_t>& s) {
  if (s.empty() || s[0] < 1) return false;
  if (s.size() == 2) return s[1] % 3 == 0 && familyJoints(s[1] / 3);
  if (s.size() == 3) return familyJoints(s[1]) && s[2] == 3;
  return s.size() == 4 && familyJoints(s[1]) && s[2] == 3 && s[3] == 3;
}

bool matchesBarePoses(const DataNode& root) {
  return root.isArray() && !root.array.isString() && barePoseShape(root.array.shape);
}

// Distance from joint 0 to joint `j` in frame `f` of a (T,24,3) array.
double boneLength(const Array& a, int64_t f, int64_t j) {
  const double* p = a.data.data() + f * 72;
  const double dx = p[3 * j] - p[0], dy = p[3 * j + 1] - p[1], dz = p[3 * j + 2] - p[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// True when a (T,24,3) array looks like joint positions: over T >= 2 frames,
// the pelvis-to-hip and pelvis-to-spine distances (joints 1, 2, 3) keep one
// length between 2 and 50 cm. Axis-angle triples of a moving body do not.
// NaN compares false: such an array is left to decodeRotations' check.
bool rigidBones(const Array& a) {
  const auto& s = a.shape;
  if (s.size() != 3 || s[1] != 24 || s[0] < 2) return false;
  for (int64_t j = 1; j <= 3; ++j) {
    const double first = boneLength(a, 0, j);
    if (!(first >= 0.02 && first <= 0.5)) return false;
    for (int64_t f = 1; f < s[0]; ++f)
      if (!(std::abs(boneLength(a, f, j) - first) <= 1e-3 * first)) return false;
  }
  return true;
}

Status decodeBarePoses(const DataNode& root, const std::string& path, Motion* m) {
  const Array& a = root.array;
  if (rigidBones(a))
    return makeError(path + ": a bare array " + shapeString(a.shape) +
                     " of joint positions (constant bone lengths), not rotations: fit a body "
                     "first, e.g. with SMPLify");
  if (Status st = decodeRotations(a, path, m); !st) return st;
  m->translation.assign(m->frames.size(), Eigen::Vector3d::Zero());
  m->world = MotionWorld::Y;
  m->fps = 0.0;  // not stored: the row's 30 fps, with the note
  const bool matrices = a.shape.size() == 4;
  const int64_t joints = a.shape.size() == 2 ? a.shape[1] / 3 : a.shape[1];
  m->notes.insert(m->notes.begin(),
                  "a bare pose array " + shapeString(a.shape) + ": read as " +
                      modelKindLabel(m->layout) + " poses (" + std::to_string(joints) +
                      " joints, " + (matrices ? "rotation matrices" : "axis-angle") +
                      ") in the model's joint order; no translation or betas in the file");
  return Status();
}

}  // namespace

const MotionLayout& barePosesLayout() {
  static const MotionLayout row{
      "bare_poses",
      "a bare pose array (T,3K), (T,K,3) or (T,K,3,3), K = 24, 52, 55 or 16",
      kNpyFile | kTorchFile | kPickleFile | kJoblibFile,
      matchesBarePoses,
      {},
      motion_detail::oneTrack<decodeBarePoses>};
  return row;
}

}  // namespace smpl
