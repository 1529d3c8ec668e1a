#include "core/motions/motion_mdm.h"

#include <Eigen/Geometry>

#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

using motion_detail::find;
using motion_detail::has;

bool matchesMdm(const DataNode& root) {
  const bool thetas = has(root, "thetas"), root_translation = has(root, "root_translation");
  return root.isDict() &&
         ((has(root, "motion") && (thetas || root_translation)) || (thetas && root_translation));
}

// The 6D rows (J,6,T) and the root positions (3,T) as MDM's arrays lay them out.
struct Source {
  const Array* six = nullptr;   // (J,6,T), J >= 24: rows 0-23 read
  const Array* root = nullptr;  // (25,6,T) `motion` row 24, or (3,T) `root_translation`
  int64_t frames = 0;
  bool packed = false;  // root position in six's row 24
};

Result<Source> sourceOf(const DataNode& d, const std::string& path) {
  Source s;
  if (const Array* motion = find(d, "motion")) {
    if (motion->shape.size() != 3 || motion->shape[0] != 25 || motion->shape[1] != 6 ||
        motion->shape[2] < 1)
      return makeError(path + ": 'motion' has shape " + shapeString(motion->shape) +
                       "; expected (25,6,T) (24 joints' 6D rotations and the root position)");
    s.six = s.root = motion;
    s.packed = true;
  } else {
    s.six = find(d, "thetas");
    s.root = find(d, "root_translation");
    if (!s.six || !s.root)
      return makeError(path +
                       ": 'motion' is absent, so 'thetas' (24,6,T) and "
                       "'root_translation' (3,T) are needed");
    if (s.six->shape.size() != 3 || s.six->shape[0] != 24 || s.six->shape[1] != 6 ||
        s.six->shape[2] < 1)
      return makeError(path + ": 'thetas' has shape " + shapeString(s.six->shape) +
                       "; expected (24,6,T) 6D rotations");
    if (s.root->shape != std::vector<int64_t>{3, s.six->shape[2]})
      return makeError(path + ": 'root_translation' has shape " + shapeString(s.root->shape) +
                       "; expected (3," + std::to_string(s.six->shape[2]) + ")");
  }
  s.frames = s.six->shape[2];
  if (Status st = motion_detail::checkNumbers(*s.six, path, s.packed ? "motion" : "thetas"); !st)
    return st.error();
  if (!s.packed)
    if (Status st = motion_detail::checkNumbers(*s.root, path, "root_translation"); !st)
      return st.error();
  return s;
}

// Root position of frame f (metres).
Eigen::Vector3d rootAt(const Source& s, int64_t f) {
  const int64_t t = s.frames;
  const int64_t base = s.packed ? 24 * 6 * t : 0;  // motion[24, c, f] or root_translation[c, f]
  return Eigen::Vector3d(s.root->data[base + 0 * t + f], s.root->data[base + 1 * t + f],
                         s.root->data[base + 2 * t + f]);
}

Status decodeMdm(const DataNode& d, const std::string& path, Motion* m) {
  Result<Source> s = sourceOf(d, path);
  if (!s) return s.error();
  const int64_t t = s->frames;
  m->layout = ModelKind::Smpl;
  if (Status st = motion_detail::allocateFrames(t, 24, path, m); !st) return st;
  m->translation.resize(t);
  const Eigen::Vector3d origin = rootAt(*s, 0);
  for (int64_t f = 0; f < t; ++f) {
    for (int64_t j = 0; j < 24; ++j) {
      double a[6];
      for (int64_t c = 0; c < 6; ++c) a[c] = s->six->data[(j * 6 + c) * t + f];  // (J,6,T)
      Result<Eigen::Matrix3d> r =
          rotationFrom6d(a, "frame " + std::to_string(f) + " joint " + std::to_string(j));
      if (!r) return makeError(path + ": " + r.message());
      m->frames[f][j] = *r;
    }
    m->translation[f] = rootAt(*s, f) - origin;
  }
  m->world = MotionWorld::Y;
  m->fps = 0.0;  // not stored: the row's 20 fps, with the note
  m->notes.push_back(
      "read as MDM SMPL parameters (6D rotations, the first two rows of each matrix as "
      "PyTorch3D; root translation relative to frame 0, as MDM's meshes; zero betas)");
  return Status();
}

}  // namespace

Result<Eigen::Matrix3d> rotationFrom6d(const double a[6], const std::string& what) {
  const Eigen::Vector3d a1(a[0], a[1], a[2]), a2(a[3], a[4], a[5]);
  const double n1 = a1.norm();
  if (!(n1 > 1e-12)) return makeError("the 6D rotation of " + what + " has a zero first vector");
  const Eigen::Vector3d b1 = a1 / n1;
  const Eigen::Vector3d rest = a2 - b1.dot(a2) * b1;
  // Parallel vectors leave only rounding (float32: ~1e-7 of |a2|): no second row.
  if (!(rest.norm() > 1e-6 * a2.norm()) || !(rest.norm() > 1e-12))
    return makeError("the 6D rotation of " + what +
                     " has a second vector that is zero or parallel to the first");
  const Eigen::Vector3d b2 = rest.normalized();
  Eigen::Matrix3d r;
  r.row(0) = b1;
  r.row(1) = b2;
  r.row(2) = b1.cross(b2);
  return r;
}

const MotionLayout& mdmLayout() {
  static const MotionLayout row{
      "mdm",
      "MDM SMPL parameters (*_smpl_params.npy: motion (25,6,T) 6D rotations)",
      kNpyFile | kPickleFile,
      matchesMdm,
      {"motion", "thetas", "root_translation"},
      motion_detail::oneTrack<decodeMdm>,
      20.0,
      "MDM (HumanML3D) stores no frame rate; its documentation gives 20 fps"};
  return row;
}

}  // namespace smpl
