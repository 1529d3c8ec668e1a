#include "core/motions/motion_multihmr.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/joint_names.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {
using motion_detail::find;
using motion_detail::has;

bool matchesMultiHmr(const DataNode& root) {
  return root.isDict() && has(root, "rotvec") && has(root, "transl_pelvis");
}

// Multi-HMR's 53 joints (SMPL_Layer.forward's slices) by their SMPL-X names.
std::vector<std::string> rotvecJointNames() {
  const std::vector<std::string>& x = canonicalJointNames(ModelKind::SmplX);
  std::vector<std::string> names(x.begin(), x.begin() + 22);  // pelvis .. right_wrist
  names.insert(names.end(), x.begin() + 25, x.begin() + 55);  // left then right fingers
  names.push_back("jaw");
  return names;
}

// The SMPL-X joint index of each of the 53 rotvec joints, by name.
Result<std::vector<int>> rotvecToSmplx(const std::string& path) {
  const std::vector<std::string>& x = canonicalJointNames(ModelKind::SmplX);
  std::vector<int> index;
  for (const std::string& name : rotvecJointNames()) {
    const auto it = std::find(x.begin(), x.end(), name);
    if (it == x.end()) return makeError(path + ": no SMPL-X joint '" + name + "'");
    index.push_back(static_cast<int>(it - x.begin()));
  }
  return index;
}

// `key` as P rows of `width` numbers ((P,width) or (P,1,width), (P,53,3) for
// width 159), else the shape error.
Result<const Array*> rows(const DataNode& d, const std::string& path, const char* key, int64_t p,
                          int64_t width, const char* what) {
  const Array* a = find(d, key);
  if (!a) return makeError(path + ": missing key '" + std::string(key) + "'");
  if (Status s = motion_detail::checkNumbers(*a, path, key); !s) return s.error();
  const bool ok =
      !a->shape.empty() && (p < 0 || a->shape[0] == p) &&
      (width < 0 ? a->shape.size() == 2 : a->shape.size() >= 2 && a->size() == a->shape[0] * width);
  if (!ok)
    return makeError(path + ": '" + key + "' has shape " + shapeString(a->shape) + "; expected " +
                     what);
  return a;
}

Status decodeMultiHmr(const DataNode& d, const LayoutInput& in, MotionSet* out) {
  Result<const Array*> rotvec =
      rows(d, in.path, "rotvec", -1, 159, "(P,53,3) axis-angle (root, body, hands, jaw)");
  if (!rotvec) return rotvec.error();
  const int64_t persons = (*rotvec)->shape[0];
  if (persons == 0) {  // an image without a detection: nothing in a sequence, an error alone
    if (!in.options.frame_file)
      return makeError(in.path + ": no person in this image ('rotvec' is empty)");
    out->notes.push_back("read as Multi-HMR output (images without a person contribute no frame)");
    return Status();
  }
  const std::string per = "(" + std::to_string(persons);
  Result<const Array*> pelvis =
      rows(d, in.path, "transl_pelvis", persons, 3, (per + ",1,3) pelvis positions").c_str());
  if (!pelvis) return pelvis.error();
  Result<const Array*> shape = rows(d, in.path, "shape", persons, -1, (per + ",B) betas").c_str());
  if (!shape) return shape.error();
  const Array* expression = nullptr;
  if (has(d, "expression")) {
    Result<const Array*> e =
        rows(d, in.path, "expression", persons, -1, (per + ",E) expression coefficients").c_str());
    if (!e) return e.error();
    expression = *e;
  }
  Result<std::vector<int>> joint = rotvecToSmplx(in.path);
  if (!joint) return joint.error();
  const int64_t betas = (*shape)->shape[1];
  for (int64_t p = 0; p < persons; ++p) {
    Motion m;
    m.layout = ModelKind::SmplX;
    m.track = std::to_string(p);
    if (Status s = motion_detail::allocateFrames(1, 55, in.path, &m); !s) return s;
    const double* pose = (*rotvec)->data.data() + 159 * p;
    for (int k = 0; k < 53; ++k)
      motion_detail::putAxisAngle(pose + 3 * k, 1, (*joint)[k], &m.frames[0]);
    m.translation = {Eigen::Map<const Eigen::Vector3d>((*pelvis)->data.data() + 3 * p)};
    m.translation_anchor = {"pelvis"};  // transl_pelvis is where the posed pelvis is
    m.betas.assign((*shape)->data.begin() + betas * p, (*shape)->data.begin() + betas * (p + 1));
    if (expression) {
      const int64_t e = expression->shape[1];
      Array row;
      row.shape = {1, e};
      row.data.assign(expression->data.begin() + e * p, expression->data.begin() + e * (p + 1));
      if (Status s = motion_detail::readExpression(row, in.path, "expression", &m); !s) return s;
    }
    m.world = MotionWorld::CameraYDown;
    m.world_why = "Multi-HMR's parameters are in the camera frame";
    m.fps = 0.0;
    out->tracks.push_back(std::move(m));
  }
  out->notes.push_back("read as Multi-HMR output (" + std::to_string(persons) +
                       (persons == 1 ? " person" : " persons, one track each in row order") +
                       "; SMPL-X, absolute finger rotations: flat_hand_mean=True)");
  out->notes.push_back(
      "'transl_pelvis' is the posed pelvis: the translation is it minus the rest pelvis J_0 of "
      "the betas");
  std::string ignored;
  for (const char* key : {"transl", "scores", "loc", "dist"})
    if (has(d, key)) ignored += (ignored.empty() ? "" : ", ") + std::string(key);
  if (!ignored.empty())
    out->notes.push_back("ignored: " + ignored +
                         " ('transl' is the primary keypoint's location, not the body's "
                         "translation; the others describe the detection)");
  return Status();
}

}  // namespace

const MotionLayout& multiHmrLayout() {
  static const MotionLayout row{
      "multihmr",
      "Multi-HMR per-image output (rotvec, shape, transl_pelvis)",
      kNpzFile | kPickleFile,
      matchesMultiHmr,
      {"rotvec", "shape", "expression", "transl_pelvis", "transl", "scores", "loc", "dist"},
      decodeMultiHmr};
  return row;
}

}  // namespace smpl
