#include "core/motions/motion_beat2.h"

#include "core/models/betas_rows.h"
#include "core/models/validate_inputs.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {
using motion_detail::find;
using motion_detail::has;

bool matchesBeat2(const DataNode& root) {
  return has(root, "poses") && (has(root, "expressions") || has(root, "model")) &&
         !has(root, "surface_model_type") && !has(root, "root_orient") && !has(root, "pose_body");
}

Status decodePoses(const Array& poses, const std::string& path, Motion* m) {
  const auto& s = poses.shape;
  const bool flat = s.size() == 2 && s[1] == 165, split = s.size() == 3 && s[1] == 55 && s[2] == 3;
  if ((!flat && !split) || s[0] < 1)
    return makeError(path + ": 'poses' has shape " + shapeString(s) +
                     "; expected (T,165) SMPL-X axis-angle");
  if (Status st = motion_detail::checkNumbers(poses, path, "poses"); !st) return st;
  const int64_t t = s[0];
  m->layout = ModelKind::SmplX;
  if (Status st = motion_detail::allocateFrames(t, 55, path, m); !st) return st;
  for (int64_t f = 0; f < t; ++f) {
    const double* p = poses.data.data() + 165 * f;
    motion_detail::putAxisAngle(p, 25, 0, &m->frames[f]);  // root, body, jaw, eyes
    m->hands.left.push_back(Eigen::Map<const Eigen::VectorXd>(p + 75, 45));  // + hands_mean
    m->hands.right.push_back(Eigen::Map<const Eigen::VectorXd>(p + 120, 45));
  }
  return Status();
}

Status decodeExtras(const DataNode& d, const std::string& path, Motion* m) {
  const int64_t t = static_cast<int64_t>(m->frames.size());
  m->translation.assign(t, Eigen::Vector3d::Zero());
  if (const Array* tr = find(d, "trans")) {
    if (tr->shape != std::vector<int64_t>{t, 3})
      return makeError(path + ": 'trans' has shape " + shapeString(tr->shape) + "; expected (" +
                       std::to_string(t) + ",3)");
    if (Status st = motion_detail::checkNumbers(*tr, path, "trans"); !st) return st;
    for (int64_t f = 0; f < t; ++f)
      m->translation[f] = Eigen::Map<const Eigen::Vector3d>(tr->data.data() + 3 * f);
  }
  if (const Array* b = find(d, "betas"); b && !b->isString()) {
    Result<BetasRows> rows = collapseBetasRows(*b, path);
    if (!rows) return rows.error();
    m->betas = rows->betas;
    if (rows->averaged) m->notes.push_back(betasRowsNote(*rows));
  }
  if (const Array* e = find(d, "expressions"))
    if (Status st = motion_detail::readExpression(*e, path, "expressions", m); !st) return st;
  if (const Array* g = find(d, "gender"); g && !g->strings.empty()) m->gender = g->strings[0];
  m->fps = 0.0;
  if (const Array* r = find(d, "mocap_frame_rate"); r && !r->isString() && r->data.size() == 1) {
    if (Status st = checkFrameRate(r->data[0], path, "'mocap_frame_rate'"); !st) return st;
    m->fps = r->data[0];
  }
  return Status();
}

Status decodeBeat2(const DataNode& d, const std::string& path, Motion* m) {
  const Array* poses = find(d, "poses");
  if (!poses) return makeError(path + ": 'poses' is not an array of numbers");
  if (Status st = decodePoses(*poses, path, m); !st) return st;
  m->world = MotionWorld::Y;
  m->notes.push_back(
      "read as BEAT2 / EMAGE output (Y-up world; hands relative to the model's "
      "hands_mean, as its smplx call with flat_hand_mean=False)");
  return decodeExtras(d, path, m);
}

}  // namespace

const MotionLayout& beat2Layout() {
  static const MotionLayout row{
      "beat2",
      "BEAT2 / EMAGE talking body (poses, expressions)",
      kNpzFile | kPickleFile,
      matchesBeat2,
      {"poses", "expressions", "trans", "betas", "gender", "mocap_frame_rate", "model"},
      motion_detail::oneTrack<decodeBeat2>};
  return row;
}

}  // namespace smpl
