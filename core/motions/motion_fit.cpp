#include "core/motions/motion_fit.h"

#include <algorithm>
#include <cstdio>

#include "core/joint_names.h"
#include "core/models/validate_inputs.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace motion_detail {
namespace {

int64_t product(const std::vector<int64_t>& s, size_t n) {
  int64_t p = 1;
  for (size_t i = 0; i < n; ++i) p *= s[i];
  return p;
}

// Frames of a part with `joints` joints per frame read as rotation matrices
// ((...,J,3,3), (...,9J); one joint also (...,3,3)) or axis-angle ((...,J,3),
// (...,3J)); 0 if the shape does not fit that reading.
int64_t framesAs(const std::vector<int64_t>& s, int joints, bool matrices) {
  const size_t n = s.size();
  if (matrices) {
    if (n >= 3 && s[n - 1] == 3 && s[n - 2] == 3 && s[n - 3] == joints) return product(s, n - 3);
    if (joints == 1 && n >= 2 && s[n - 1] == 3 && s[n - 2] == 3) return product(s, n - 2);
    if (n >= 1 && s[n - 1] == 9 * joints && joints > 1) return product(s, n - 1);
    return 0;
  }
  if (n >= 2 && s[n - 1] == 3 && s[n - 2] == joints) return product(s, n - 2);
  if (n >= 1 && s[n - 1] == 3 * joints) return product(s, n - 1);
  return 0;
}

// The reading that gives `t` frames (axis-angle first); false if none does.
bool matchPart(const std::vector<int64_t>& s, int joints, int64_t t, bool* matrices) {
  for (bool m : {false, true})
    if (framesAs(s, joints, m) == t) return *matrices = m, true;
  return false;
}

// Frames of body_pose with `joints` joints, 0 if its shape does not fit.
int64_t framesOf(const std::vector<int64_t>& s, int joints, bool* matrices) {
  for (bool m : {true, false})
    if (int64_t t = framesAs(s, joints, m); t > 0) return *matrices = m, t;
  return 0;
}

// Optional part with `joints` joints and T frames into joints [first, ...).
// A pose key that is there but is not an array (a dict, a list of objects)
// is an error naming what it holds: never a silent rest pose.
Status notAnArray(const DataNode& d, const std::string& path, const char* key) {
  const DataNode* node = d.get(key);
  if (!node || node->isArray() || node->kind == DataNode::Kind::None) return Status();
  return makeError(path + ": '" + key + "' holds " + describeNode(*node) +
                   ", expected an array of poses");
}

Status putPart(const DataNode& d, const std::string& path, const char* key, int joints, int first,
               Motion* m) {
  if (Status s = notAnArray(d, path, key); !s) return s;
  const Array* a = find(d, key);
  if (!a) return Status();
  const int64_t t = static_cast<int64_t>(m->frames.size());
  bool matrices = false;
  if (!matchPart(a->shape, joints, t, &matrices))
    return makeError(path + ": '" + key + "' has shape " + shapeString(a->shape) + "; expected " +
                     std::to_string(t) + " frame(s) of " + std::to_string(joints) +
                     " axis-angle triples or 3x3 rotation matrices");
  if (Status s = checkNumbers(*a, path, key); !s) return s;
  const int64_t stride = (matrices ? 9 : 3) * joints;
  for (int64_t f = 0; f < t; ++f)
    (matrices ? putMatrices : putAxisAngle)(a->data.data() + f * stride, joints, first,
                                            &m->frames[f]);
  return Status();
}

// A hand: matrices go in directly; axis-angle (full 45 or C < 45 PCA
// coefficients) waits for the model in `pending`.
Status putHand(const DataNode& d, const std::string& path, const char* key, int first, Motion* m,
               std::vector<Eigen::VectorXd>* pending) {
  if (Status s = notAnArray(d, path, key); !s) return s;
  const Array* a = find(d, key);
  if (!a) return Status();
  const int64_t t = static_cast<int64_t>(m->frames.size());
  if (framesAs(a->shape, 15, true) == t) return putPart(d, path, key, 15, first, m);
  const int64_t c = t > 0 && a->size() % t == 0 ? a->size() / t : 0;
  if (c < 1 || c > 45 || a->shape.empty() ||
      (c == 45 ? framesAs(a->shape, 15, false) != t : product(a->shape, a->shape.size() - 1) != t))
    return makeError(path + ": '" + key + "' has shape " + shapeString(a->shape) + "; expected (" +
                     std::to_string(t) + ",45) axis-angle, (" + std::to_string(t) +
                     ",C) PCA coefficients with C < 45, or (" + std::to_string(t) +
                     ",15,3,3) rotation matrices");
  if (Status s = checkNumbers(*a, path, key); !s) return s;
  for (int64_t f = 0; f < t; ++f)
    pending->push_back(Eigen::Map<const Eigen::VectorXd>(a->data.data() + f * c, c));
  return Status();
}

// Rows of a (R,N) array: identical -> that row, else their mean (note).
// Rows are compared as stored, not against their mean: the mean of 30 equal
// float32 rows, summed in double, differs from them by rounding, and such a
// file (MHR's SMPL-X converter repeats its betas per frame) has one row.
std::vector<double> oneRow(const Array& a, const char* key, Motion* m) {
  const int64_t n = a.shape.empty() ? 1 : a.shape.back(), rows = n > 0 ? a.size() / n : 0;
  bool identical = true;
  for (int64_t r = 1; r < rows && identical; ++r)
    identical = std::equal(a.data.begin() + r * n, a.data.begin() + (r + 1) * n, a.data.begin());
  if (identical)
    return rows > 0 ? std::vector<double>(a.data.begin(), a.data.begin() + n)
                    : std::vector<double>(n, 0.0);
  std::vector<double> mean(n, 0.0);
  double deviation = 0.0;
  for (int64_t r = 0; r < rows; ++r)
    for (int64_t i = 0; i < n; ++i) mean[i] += a.data[r * n + i] / rows;
  for (int64_t r = 0; r < rows; ++r)
    for (int64_t i = 0; i < n; ++i)
      deviation = std::max(deviation, std::abs(a.data[r * n + i] - mean[i]));
  {
    char text[160];
    std::snprintf(text, sizeof text,
                  "'%s' has %lld different rows: their mean is used (largest deviation %.3g)", key,
                  static_cast<long long>(rows), deviation);
    m->notes.push_back(text);
  }
  return mean;
}

Status readExtras(const DataNode& d, const std::string& path, Motion* m) {
  const int64_t t = static_cast<int64_t>(m->frames.size());
  m->translation.assign(t, Eigen::Vector3d::Zero());
  if (const Array* a = find(d, "transl")) {
    if (a->size() != 3 * t || a->shape.empty() || a->shape.back() != 3)
      return makeError(path + ": 'transl' has shape " + shapeString(a->shape) + "; expected (" +
                       std::to_string(t) + ",3)");
    if (Status s = checkNumbers(*a, path, "transl"); !s) return s;
    for (int64_t f = 0; f < t; ++f)
      m->translation[f] = Eigen::Map<const Eigen::Vector3d>(a->data.data() + 3 * f);
  }
  if (const Array* b = find(d, "betas")) {
    if (Status s = checkNumbers(*b, path, "betas"); !s) return s;
    m->betas = oneRow(*b, "betas", m);
  }
  if (const Array* g = find(d, "gender"); g && !g->strings.empty()) m->gender = g->strings[0];
  if (const Array* e = find(d, "expression"))  // baked with --expression-keys
    if (Status s = readExpression(*e, path, "expression", m); !s) return s;
  m->fps = 0.0;
  for (const char* key : {"fps", "frame_rate", "mocap_framerate"})
    if (const Array* r = find(d, key); r && !r->isString() && r->data.size() == 1) {
      if (Status s = checkFrameRate(r->data[0], path, "'" + std::string(key) + "'"); !s) return s;
      m->fps = r->data[0];
      break;
    }
  return Status();
}

}  // namespace

// SMPLify-X results place the body in the camera (smplifyx/fit_single_frame.py
// `camera_rotation` (1,3,3), `camera_translation` (1,3); smplifyx/camera.py
// p_cam = R p + t, OpenCV axes): a per-frame frame change in a camera frame.
Status readCamera(const DataNode& d, const std::string& path, Motion* m) {
  const Array* t = find(d, "camera_translation");
  if (!t || find(d, "transl")) return Status();
  const size_t frames = m->frames.size();
  if (Status s = checkNumbers(*t, path, "camera_translation"); !s) return s;
  if (t->size() != 3 && t->size() != static_cast<int64_t>(3 * frames))
    return makeError(path + ": 'camera_translation' has shape " + shapeString(t->shape) +
                     "; expected (1,3) or (" + std::to_string(frames) + ",3)");
  const Array* r = find(d, "camera_rotation");
  if (r && r->size() != 9 && r->size() != static_cast<int64_t>(9 * frames))
    return makeError(path + ": 'camera_rotation' has shape " + shapeString(r->shape) +
                     "; expected (1,3,3) or (" + std::to_string(frames) + ",3,3)");
  if (r)
    if (Status s = checkNumbers(*r, path, "camera_rotation"); !s) return s;
  for (size_t f = 0; f < frames; ++f) {
    const size_t tf = t->size() == 3 ? 0 : f, rf = r && r->size() == 9 ? 0 : f;
    m->world_translation.push_back(Eigen::Map<const Eigen::Vector3d>(t->data.data() + 3 * tf));
    Rotations one(1);
    if (r)
      putMatrices(r->data.data() + 9 * rf, 1, 0, &one);
    else
      one[0].setIdentity();
    m->world_rotation.push_back(one[0]);
  }
  m->world = MotionWorld::CameraYDown;
  m->world_why = "SMPLify-X places the body in the camera: a camera frame";
  return Status();
}

// SMPLify-X with use_vposer writes the latent as 'body_pose' (32 values).
Status refuseLatent(const Array& body, const std::string& path) {
  const int64_t last = body.shape.empty() ? 0 : body.shape.back();
  if (last != 32) return Status();
  return makeError(path +
                   ": a VPoser latent: decode it with VPoser first ('body_pose' has 32 values "
                   "per frame)");
}

Status decodeFit(const DataNode& d, const std::string& path, Motion* m) {
  const Array* body = find(d, "body_pose");
  if (!body)
    return makeError(path + ": missing key 'body_pose' (a fit with 'global_orient' needs it)");
  if (Status s = refuseLatent(*body, path); !s) return s;
  bool matrices = false;
  int64_t t = framesOf(body->shape, 21, &matrices);
  int joints = 21;
  if (t == 0 && (t = framesOf(body->shape, 23, &matrices)) > 0) joints = 23;
  if (t <= 0)
    return makeError(path + ": 'body_pose' has shape " + shapeString(body->shape) +
                     "; expected 21 joints (SMPL-X/SMPL-H: (T,63), (T,21,3), (T,21,3,3)) or 23 "
                     "(SMPL: (T,69), ...)");
  m->layout = joints == 21 ? ModelKind::SmplX : ModelKind::Smpl;
  if (Status s = allocateFrames(t, canonicalJointNames(m->layout).size(), path, m); !s) return s;
  if (!find(d, "global_orient")) m->notes.push_back("no 'global_orient': the root stays at rest");
  if (Status s = putPart(d, path, "global_orient", 1, 0, m); !s) return s;
  if (Status s = putPart(d, path, "body_pose", joints, 1, m); !s) return s;
  if (m->layout == ModelKind::SmplX) {
    const char* face[] = {"jaw_pose", "leye_pose", "reye_pose"};
    for (int i = 0; i < 3; ++i)
      if (Status s = putPart(d, path, face[i], 1, 22 + i, m); !s) return s;
    if (Status s = putHand(d, path, "left_hand_pose", 25, m, &m->hands.left); !s) return s;
    if (Status s = putHand(d, path, "right_hand_pose", 40, m, &m->hands.right); !s) return s;
  }
  if (Status s = readExtras(d, path, m); !s) return s;
  return readCamera(d, path, m);
}

}  // namespace motion_detail

namespace {

// One side: coefficients -> 45-d axis-angle per the reference, into joints [first, first+15).
Status resolveSide(const BodyModel& model, bool flat, const std::string& context, const char* side,
                   const Eigen::MatrixXd& components, const Eigen::VectorXd& mean, int first,
                   Motion* m, const std::vector<Eigen::VectorXd>& coefficients) {
  const std::string suffix = side;
  for (size_t f = 0; f < coefficients.size(); ++f) {
    const Eigen::Index c = coefficients[f].size();
    Eigen::VectorXd pose = coefficients[f];
    if (c < 45) {
      if (components.rows() < c)
        return makeError(context + ": " + std::to_string(c) +
                         " PCA hand coefficients need 'hands_components" + suffix +
                         "' with at least " + std::to_string(c) + " rows in the model " +
                         model.name + " (it has " + std::to_string(components.rows()) + ")");
      pose = components.topRows(c).transpose() * coefficients[f];
    }
    if (!flat && mean.size() != 45 && !m->hands.rest_without_mean.empty()) {
      // no mean to add: the hand stays as given (rest, for GVHMR's zeros); noted by the caller
    } else if (!flat) {
      if (mean.size() != 45)
        return makeError(context + ": the hand pose is relative to the mean hand, but the model " +
                         model.name + " has no 'hands_mean" + suffix +
                         "' (give --flat-hand-mean if the poses are flat-hand relative)");
      pose += mean;
    }
    motion_detail::putAxisAngle(pose.data(), 15, first, &m->frames[f]);
  }
  return Status();
}

}  // namespace

Status resolveFitHands(const BodyModel& model, bool flat_hand_mean, const std::string& context,
                       Motion* m) {
  if (!m->hands.active()) return Status();
  const auto& names = model.joint_names;
  if (std::find(names.begin(), names.end(), "left_index1") == names.end()) {
    m->notes.push_back("the fit's hand poses are dropped: the model " + model.name +
                       " has no finger joints");
    m->hands = PendingHands();
    return Status();
  }
  const int left = m->layout == ModelKind::SmplX ? 25 : 22;
  if (!flat_hand_mean && !m->hands.rest_without_mean.empty() &&
      (model.hands_mean_l.size() != 45 || model.hands_mean_r.size() != 45))
    m->notes.push_back(m->hands.rest_without_mean);
  if (Status s = resolveSide(model, flat_hand_mean, context, "l", model.hands_components_l,
                             model.hands_mean_l, left, m, m->hands.left);
      !s)
    return s;
  if (Status s = resolveSide(model, flat_hand_mean, context, "r", model.hands_components_r,
                             model.hands_mean_r, left + 15, m, m->hands.right);
      !s)
    return s;
  m->hands = PendingHands();
  return Status();
}

namespace {
bool matchesFit(const DataNode& root) {
  return motion_detail::has(root, "body_pose") || motion_detail::has(root, "global_orient");
}
}  // namespace

const MotionLayout& fitLayout() {
  static const MotionLayout row{
      "fit",
      "SMPL-X / SMPL fit (SMPLify-X, PIXIE, ExPose)",
      kAnyContainer,
      matchesFit,
      {"global_orient", "body_pose", "left_hand_pose", "right_hand_pose", "jaw_pose", "leye_pose",
       "reye_pose", "expression", "betas", "transl", "gender", "fps", "frame_rate",
       "mocap_framerate", "camera_translation", "camera_rotation"},
      motion_detail::oneTrack<motion_detail::decodeFit>};
  return row;
}

}  // namespace smpl
