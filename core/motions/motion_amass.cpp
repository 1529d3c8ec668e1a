#include "core/motions/motion_amass.h"

#include <cmath>

#include "core/joint_names.h"
#include "core/models/betas_rows.h"
#include "core/models/validate_inputs.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {
using motion_detail::find;

// Concatenate SMPL-X AMASS split keys into one (T,165) pose array.
Result<Array> joinSplitPoses(const DataNode& d, const std::string& path) {
  const char* keys[] = {"root_orient", "pose_body", "pose_jaw", "pose_eye", "pose_hand"};
  const int64_t widths[] = {3, 63, 3, 6, 90};
  const Array* root = find(d, "root_orient");
  if (!root) return makeError(path + ": 'root_orient' is not an array");
  const int64_t t = root->shape.empty() ? 0 : root->shape[0];
  Array joined;
  joined.shape = {t, 165};
  if (Status st = joined.charge.add(static_cast<uint64_t>(t) * 165 * sizeof(double), path,
                                    "joining the pose keys");
      !st)
    return st.error();
  joined.data.assign(t * 165, 0.0);
  int64_t column = 0;
  for (int i = 0; i < 5; ++i) {
    const Array* a = find(d, keys[i]);
    if (a && (a->shape.size() != 2 || a->shape[0] != t || a->shape[1] != widths[i]))
      return makeError(path + ": '" + keys[i] + "' has shape " + shapeString(a->shape) +
                       "; expected (" + std::to_string(t) + "," + std::to_string(widths[i]) + ")");
    for (int64_t f = 0; a && f < t; ++f)
      for (int64_t c = 0; c < widths[i]; ++c)
        joined.data[f * 165 + column + c] = a->data[f * widths[i] + c];
    column += widths[i];
  }
  return joined;
}

// SKEL's pose vector (MarilynKeller/SKEL skel/skel_model.py: num_q_params = 46);
// no SMPL-family layout has 46 values per frame.
constexpr int64_t kSkelPoseParameters = 46;

}  // namespace

Status decodeRotations(const Array& poses, const std::string& path, Motion* m) {
  const auto& s = poses.shape;
  const bool matrices = s.size() == 4 && s[2] == 3 && s[3] == 3;
  const bool triples = (s.size() == 2 && s[1] % 3 == 0) || (s.size() == 3 && s[2] == 3);
  if (s.size() == 2 && s[1] == kSkelPoseParameters)
    return makeError(path + ": 'poses' has shape " + shapeString(s) +
                     ": SKEL pose parameters (46 anatomical degrees of freedom, as HSMR and SKEL's "
                     "aligner write them), not SMPL axis-angle; this version exports SMPL-family "
                     "motions: export the SMPL parameters of the motion (docs/motions.md \"Models "
                     "that are not SMPL\")");
  if (!matrices && !triples)
    return makeError(path + ": 'poses' has shape " + shapeString(s) +
                     "; expected (T,3J), (T,J,3) or (T,J,3,3)");
  const int64_t t = s[0], j = matrices || s.size() == 3 ? s[1] : s[1] / 3;
  if (t == 0) return makeError(path + ": 'poses' has no frames");
  if (!modelKindFromJointCount(static_cast<int>(j), &m->layout))
    return makeError(path + ": 'poses' has " + std::to_string(j) +
                     " joints; expected 24 (SMPL), 52 (SMPL-H), 55 (SMPL-X) or 16 (MANO)");
  if (Status st = motion_detail::checkNumbers(poses, path, "poses"); !st) return st;
  if (Status st = motion_detail::allocateFrames(t, static_cast<size_t>(j), path, m); !st) return st;
  const int64_t stride = matrices ? 9 * j : 3 * j;
  for (int64_t f = 0; f < t; ++f)
    (matrices ? motion_detail::putMatrices : motion_detail::putAxisAngle)(
        poses.data.data() + f * stride, static_cast<int>(j), 0, &m->frames[f]);
  return Status();
}

namespace {

// AMASS `dmpls` (T,D): soft-tissue coefficients (core/models/dmpl.h). Needed
// only with a DMPL basis, so a malformed array does not fail the load: the
// problem is kept in m->dmpls_problem for the exporter to report when used.
Status decodeDmpls(const DataNode& d, const std::string& path, Motion* m) {
  const Array* a = find(d, "dmpls");
  if (!a) return Status();
  const int64_t t = static_cast<int64_t>(m->frames.size());
  if (a->isString() || a->shape.size() != 2 || a->shape[0] != t || a->shape[1] < 1) {
    m->dmpls_problem = path + ": 'dmpls' has shape " + shapeString(a->shape) + "; expected (" +
                       std::to_string(t) + ",D) to match 'poses'";
    return Status();
  }
  if (Status st = motion_detail::checkNumbers(*a, path, "dmpls"); !st) {
    m->dmpls_problem = st.message();
    return Status();
  }
  if (Status st = m->charge.add(static_cast<uint64_t>(a->size()) * sizeof(double), path, "dmpls");
      !st)
    return st;
  m->dmpls =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          a->data.data(), a->shape[0], a->shape[1]);
  return Status();
}

Status decodeTranslation(const DataNode& d, const std::string& path, Motion* m) {
  const size_t t = m->frames.size();
  m->translation.assign(t, Eigen::Vector3d::Zero());
  const Array* trans = find(d, "trans");
  if (!trans) return Status();
  if (trans->shape.size() != 2 || trans->shape[0] != static_cast<int64_t>(t) ||
      trans->shape[1] != 3)
    return makeError(path + ": 'trans' has shape " + shapeString(trans->shape) + "; expected (" +
                     std::to_string(t) + ",3) to match 'poses'");
  if (Status st = motion_detail::checkNumbers(*trans, path, "trans"); !st) return st;
  for (size_t f = 0; f < t; ++f)
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>(trans->data.data() + 3 * f);
  return Status();
}

Status decodeExtras(const DataNode& d, const std::string& path, Motion* m) {
  if (Status st = decodeTranslation(d, path, m); !st) return st;
  if (const Array* betas = find(d, "betas");
      betas && !betas->isString()) {  // per-frame rows: betas_rows.h
    Result<BetasRows> rows = collapseBetasRows(*betas, path);
    if (!rows) return rows.error();
    m->betas = rows->betas;
    if (rows->averaged) m->notes.push_back(betasRowsNote(*rows));
  }
  if (const Array* gender = find(d, "gender"); gender && !gender->strings.empty())
    m->gender = gender->strings[0];
  if (const Array* t = find(d, "surface_model_type"); t && !t->strings.empty())  // AMASS
    for (ModelKind k : {ModelKind::Smpl, ModelKind::SmplH, ModelKind::SmplX, ModelKind::Mano})
      if (t->strings[0] == modelKindName(k)) m->model_kind = k;
  if (Status st = decodeDmpls(d, path, m); !st) return st;
  m->fps = 0.0;
  for (const char* key : {"mocap_framerate", "mocap_frame_rate", "fps"}) {
    const Array* rate = find(d, key);
    if (!rate || rate->isString() || rate->data.size() != 1) continue;
    if (Status st = checkFrameRate(rate->data[0], path, "'" + std::string(key) + "'"); !st)
      return st;
    m->fps = rate->data[0];
    if (std::string(key) != "fps") m->world = MotionWorld::Z;
    break;
  }
  if (motion_detail::has(d, "gender") || motion_detail::has(d, "root_orient"))
    m->world = MotionWorld::Z;
  return Status();
}

// `poses` or the AMASS SMPL-X split keys.
Status decodePoses(const DataNode& d, const std::string& path, Motion* m) {
  const Array* given = find(d, "poses");
  Array joined;
  if (!given) {
    if (motion_detail::has(d, "poses"))
      return makeError(path + ": 'poses' holds " + describeNode(*d.get("poses")) +
                       ", expected an array of numbers");
    Result<Array> j = joinSplitPoses(d, path);
    if (!j) return j.error();
    joined = std::move(*j);
  }
  const Array& poses = given ? *given : joined;
  if (poses.isString()) return makeError(path + ": 'poses' holds text, expected numbers");
  if (Status s = decodeRotations(poses, path, m); !s) return s;
  return decodeExtras(d, path, m);
}

bool matchesAmass(const DataNode& root) {
  return motion_detail::has(root, "poses") || motion_detail::has(root, "root_orient");
}

}  // namespace

const MotionLayout& amassLayout() {
  static const MotionLayout row{
      "amass",
      "AMASS or plain poses",
      kAnyContainer,
      matchesAmass,
      {"poses", "root_orient", "pose_body", "pose_jaw", "pose_eye", "pose_hand", "trans", "betas",
       "gender", "dmpls", "mocap_framerate", "mocap_frame_rate", "fps", "surface_model_type"},
      motion_detail::oneTrack<decodePoses>};
  return row;
}

}  // namespace smpl
