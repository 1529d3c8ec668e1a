#include "core/motions/motion_aist.h"

#include <cmath>

#include "core/motions/motion_internal.h"

namespace smpl {
namespace motion_detail {

Status decodeAist(const DataNode& d, const std::string& path, Motion* m) {
  const Array* poses = find(d, "smpl_poses");
  if (poses->shape.size() != 2 || poses->shape[1] != 72 || poses->shape[0] < 1)
    return makeError(path + ": 'smpl_poses' has shape " + shapeString(poses->shape) +
                     "; expected (T,72)");
  if (Status s = checkNumbers(*poses, path, "smpl_poses"); !s) return s;
  const int64_t t = poses->shape[0];
  const Array* trans = find(d, "smpl_trans");
  if (!trans) return makeError(path + ": missing key 'smpl_trans'");
  if (trans->shape != std::vector<int64_t>{t, 3})
    return makeError(path + ": 'smpl_trans' has shape " + shapeString(trans->shape) +
                     "; expected (" + std::to_string(t) + ",3)");
  if (Status s = checkNumbers(*trans, path, "smpl_trans"); !s) return s;
  double scaling = 1.0;
  if (const Array* sc = find(d, "smpl_scaling")) {
    if (sc->isString() || sc->data.size() != 1)
      return makeError(path + ": 'smpl_scaling' has shape " + shapeString(sc->shape) +
                       "; expected one number");
    if (!(sc->data[0] > 0) || !std::isfinite(sc->data[0]))
      return makeError(path + ": 'smpl_scaling' is " + std::to_string(sc->data[0]) +
                       "; expected a positive scale");
    scaling = sc->data[0];
  } else {
    m->notes.push_back("no 'smpl_scaling': the translation is used unscaled");
  }
  m->layout = ModelKind::Smpl;
  if (Status s = allocateFrames(t, 24, path, m); !s) return s;
  m->translation.resize(t);
  for (int64_t f = 0; f < t; ++f) {
    putAxisAngle(poses->data.data() + 72 * f, 24, 0, &m->frames[f]);
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>(trans->data.data() + 3 * f) / scaling;
  }
  m->fps = 0.0;
  return Status();
}

}  // namespace motion_detail
namespace {
bool matchesAist(const DataNode& root) { return motion_detail::has(root, "smpl_poses"); }
}  // namespace

const MotionLayout& aistLayout() {
  static const MotionLayout row{"aist",
                                "AIST++ (smpl_poses, smpl_trans, smpl_scaling)",
                                kAnyContainer,
                                matchesAist,
                                {"smpl_poses", "smpl_trans", "smpl_scaling"},
                                motion_detail::oneTrack<motion_detail::decodeAist>,
                                60.0,
                                "AIST++ stores no frame rate; its documentation gives 60 fps"};
  return row;
}

}  // namespace smpl
