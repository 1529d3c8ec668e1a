#include "core/motions/motion_smplcodec.h"

#include "core/joint_names.h"
#include "core/models/validate_inputs.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace motion_detail {
namespace {

std::string expected(int64_t t, int64_t j) {
  return "(" + std::to_string(t) + "," + std::to_string(j) + ",3)";
}

// Joint layout and body joint count (with root) from smplVersion.
Status versionLayout(const DataNode& d, const std::string& path, ModelKind* kind, int* body) {
  int version = 2;
  if (const Array* v = find(d, "smplVersion")) {
    if (v->isString() || v->data.size() != 1 || !(v->data[0] >= 0 && v->data[0] <= 100))
      return makeError(path + ": 'smplVersion' is not one integer in 0..7");
    version = static_cast<int>(v->data[0]);
  }
  switch (version) {
    case 0:
    case 6:
      *kind = ModelKind::Smpl;
      *body = 24;
      return Status();
    case 1:
      *kind = ModelKind::SmplH;
      *body = 22;
      return Status();
    case 2:
    case 7:
      *kind = ModelKind::SmplX;
      *body = 22;
      return Status();
    default:
      return makeError(
          path + ": 'smplVersion' is " + std::to_string(version) +
          " (3 SUPR, 4 SMPLPP, 5 SKEL have other skeletons); expected 0 SMPL, 1 SMPLH, 2 SMPLX, "
          "6 SMIL or 7 SMPLXS");
  }
}

// Optional (T,J,3) part pose into joints [first, first+J) of every frame.
Status putPart(const DataNode& d, const std::string& path, const char* key, int joints, int first,
               Motion* m) {
  const Array* a = find(d, key);
  if (!a) return Status();
  const int64_t t = static_cast<int64_t>(m->frames.size());
  if (a->shape != std::vector<int64_t>{t, joints, 3})
    return makeError(path + ": '" + key + "' has shape " + shapeString(a->shape) + "; expected " +
                     expected(t, joints));
  if (Status s = checkNumbers(*a, path, key); !s) return s;
  for (int64_t f = 0; f < t; ++f)
    putAxisAngle(a->data.data() + f * joints * 3, joints, first, &m->frames[f]);
  return Status();
}

Status readScalars(const DataNode& d, const std::string& path, Motion* m) {
  static const char* kGenders[] = {"neutral", "male", "female"};
  if (const Array* g = find(d, "gender")) {
    if (!g->strings.empty())
      m->gender = g->strings[0];
    else if (g->data.size() == 1 && g->data[0] >= 0 && g->data[0] <= 2)
      m->gender = kGenders[static_cast<int>(g->data[0])];
    else
      return makeError(path + ": 'gender' is not 0 (neutral), 1 (male) or 2 (female)");
  }
  if (const Array* b = find(d, "shapeParameters")) {
    if (Status s = checkNumbers(*b, path, "shapeParameters"); !s) return s;
    m->betas = b->data;
  }
  m->fps = 0.0;
  if (const Array* r = find(d, "frameRate")) {
    if (r->isString() || r->data.size() != 1)
      return makeError(path + ": 'frameRate' is not one number");
    if (Status s = checkFrameRate(r->data[0], path, "'frameRate'"); !s) return s;
    m->fps = r->data[0];
  }

  return Status();
}

Status readTranslation(const DataNode& d, const std::string& path, Motion* m) {
  const int64_t t = static_cast<int64_t>(m->frames.size());
  m->translation.assign(t, Eigen::Vector3d::Zero());
  const Array* a = find(d, "bodyTranslation");
  if (!a) return Status();
  if (a->shape != std::vector<int64_t>{t, 3})
    return makeError(path + ": 'bodyTranslation' has shape " + shapeString(a->shape) +
                     "; expected (" + std::to_string(t) + ",3)");
  if (Status s = checkNumbers(*a, path, "bodyTranslation"); !s) return s;
  for (int64_t f = 0; f < t; ++f)
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>(a->data.data() + 3 * f);
  return Status();
}

// Root from `globalOrient` (T,3) / (T,1,3) when bodyPose lacks it.
Status putRoot(const DataNode& d, const std::string& path, Motion* m) {
  const Array* a = find(d, "globalOrient");
  const int64_t t = static_cast<int64_t>(m->frames.size());
  if (!a) {
    m->notes.push_back(
        "'bodyPose' has no root joint and the file has no 'globalOrient': the root stays at rest");
    return Status();
  }
  if (a->size() != 3 * t || a->shape.empty() || a->shape[0] != t)
    return makeError(path + ": 'globalOrient' has shape " + shapeString(a->shape) + "; expected (" +
                     std::to_string(t) + ",3)");
  if (Status s = checkNumbers(*a, path, "globalOrient"); !s) return s;
  for (int64_t f = 0; f < t; ++f) putAxisAngle(a->data.data() + 3 * f, 1, 0, &m->frames[f]);
  return Status();
}

}  // namespace

Status decodeSmplCodec(const DataNode& d, const std::string& path, Motion* m) {
  int body = 0;
  if (Status s = versionLayout(d, path, &m->layout, &body); !s) return s;
  const Array* pose = find(d, "bodyPose");
  const auto& shape = pose->shape;
  if (shape.size() != 3 || shape[2] != 3 || (shape[1] != body && shape[1] != body - 1) ||
      shape[0] < 1)
    return makeError(path + ": 'bodyPose' has shape " + shapeString(shape) + "; expected (T," +
                     std::to_string(body) + ",3) with the root or (T," + std::to_string(body - 1) +
                     ",3) without it");
  const int64_t t = shape[0];
  if (const Array* count = find(d, "frameCount");
      count && (count->data.size() != 1 || count->data[0] != t))
    return makeError(
        path + ": 'bodyPose' has " + std::to_string(t) + " frames but 'frameCount' is " +
        (count->data.size() == 1 ? std::to_string(static_cast<long long>(count->data[0]))
                                 : "not a number"));
  const size_t joints = canonicalJointNames(m->layout).size();
  if (Status s = allocateFrames(t, joints, path, m); !s) return s;
  const bool with_root = shape[1] == body;
  if (Status s = putPart(d, path, "bodyPose", static_cast<int>(shape[1]), with_root ? 0 : 1, m); !s)
    return s;
  if (!with_root)
    if (Status s = putRoot(d, path, m); !s) return s;
  if (m->layout == ModelKind::SmplX) {
    if (Status s = putPart(d, path, "headPose", 3, 22, m); !s) return s;
  }
  if (m->layout != ModelKind::Smpl) {
    const int hands = m->layout == ModelKind::SmplX ? 25 : 22;
    if (Status s = putPart(d, path, "leftHandPose", 15, hands, m); !s) return s;
    if (Status s = putPart(d, path, "rightHandPose", 15, hands + 15, m); !s) return s;
  }
  if (Status s = readTranslation(d, path, m); !s) return s;
  if (const Array* e = find(d, "expressionParameters"))  // baked with --expression-keys
    if (Status s = readExpression(*e, path, "expressionParameters", m); !s) return s;
  return readScalars(d, path, m);
}

}  // namespace motion_detail
namespace {
bool matchesSmplCodec(const DataNode& root) { return motion_detail::has(root, "bodyPose"); }
}  // namespace

const MotionLayout& smplCodecLayout() {
  static const MotionLayout row{
      "smplcodec",
      "Meshcapade SMPLCodec (.smpl)",
      kNpzFile,
      matchesSmplCodec,
      {"smplVersion", "gender", "shapeParameters", "frameCount", "frameRate", "bodyTranslation",
       "bodyPose", "headPose", "leftHandPose", "rightHandPose", "expressionParameters",
       "globalOrient"},
      motion_detail::oneTrack<motion_detail::decodeSmplCodec>};
  return row;
}

}  // namespace smpl
