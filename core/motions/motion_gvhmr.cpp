#include "core/motions/motion_gvhmr.h"

#include "core/motions/motion_internal.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {

bool isDictChild(const DataNode& root, const char* key) {
  const DataNode* d = root.get(key);
  return d && d->isDict();
}

bool matchesGvhmr(const DataNode& root) {
  return root.isDict() &&
         (isDictChild(root, "smpl_params_global") || isDictChild(root, "smpl_params_incam"));
}

// `params/key` as an (L, width) array of numbers, else the shape error.
Result<const Array*> part(const DataNode& params, const std::string& group, const char* key,
                          int64_t frames, int64_t width, const std::string& path) {
  const Array* a = params.leaf(key);
  const std::string name = "'" + group + "/" + key + "'";
  if (!a) return makeError(path + ": " + name + " is missing or not an array");
  if (a->shape.size() != 2 || a->shape[0] != frames || a->shape[1] != width)
    return makeError(path + ": " + name + " has shape " + shapeString(a->shape) + "; expected (" +
                     std::to_string(frames) + "," + std::to_string(width) + ")");
  if (Status s = motion_detail::checkNumbers(*a, path, (group + "/" + key).c_str()); !s)
    return s.error();
  return a;
}

// Which parameters --source-params asks for (the world ones by default).
Result<bool> readsWorld(const DataNode& root, const LayoutInput& in) {
  const bool global = isDictChild(root, "smpl_params_global");
  const bool incam = isDictChild(root, "smpl_params_incam");
  switch (in.options.source_params) {
    case SourceParams::Global:
      if (!global) return makeError(in.path + ": --source-params global: no 'smpl_params_global'");
      return true;
    case SourceParams::Incam:
      if (!incam) return makeError(in.path + ": --source-params incam: no 'smpl_params_incam'");
      return false;
    default:
      return global;
  }
}

// Hands merged into a GVHMR params dict as Mano2Smpl-X (VincentHu19/Mano2Smpl-X
// mano2smplx.py) writes them: `left_hand_pose` / `right_hand_pose`, 15 finger
// joints in SMPL-X order as axis-angle, for an SMPL-X with flat_hand_mean=True
// (its README), so the rotations are absolute: put as they are, no mean added.
// (L,45) or (L,15,3); returns whether the side was there.
Result<bool> putAbsoluteHand(const DataNode& params, const std::string& group, const char* key,
                             int first, const std::string& path, Motion* m) {
  const DataNode* node = params.get(key);
  if (!node) return false;
  const Array* a = params.leaf(key);
  const int64_t frames = static_cast<int64_t>(m->frames.size());
  const bool ok =
      a &&
      ((a->shape.size() == 2 && a->shape[0] == frames && a->shape[1] == 45) ||
       (a->shape.size() == 3 && a->shape[0] == frames && a->shape[1] == 15 && a->shape[2] == 3));
  if (!ok)
    return makeError(path + ": '" + group + "/" + key + "' is " +
                     (a ? "of shape " + shapeString(a->shape) : describeNode(*node)) +
                     "; expected (" + std::to_string(frames) + ",45) axis-angle finger poses");
  if (Status s = motion_detail::checkNumbers(*a, path, (group + "/" + key).c_str()); !s)
    return s.error();
  for (int64_t f = 0; f < frames; ++f)
    motion_detail::putAxisAngle(a->data.data() + 45 * f, 15, first, &m->frames[f]);
  return true;
}

Status decodePoses(const DataNode& params, const std::string& group, const std::string& path,
                   Motion* m) {
  const Array* body = params.leaf("body_pose");
  const int64_t frames = body && !body->shape.empty() ? body->shape[0] : 0;
  if (frames < 1)
    return makeError(path + ": '" + group + "/body_pose' is " +
                     (params.get("body_pose") ? describeNode(*params.get("body_pose"))
                                              : std::string("missing")) +
                     "; expected (L,63) SMPL-X body axis-angle");
  Result<const Array*> pose = part(params, group, "body_pose", frames, 63, path);
  if (!pose) return pose.error();
  Result<const Array*> root = part(params, group, "global_orient", frames, 3, path);
  if (!root) return root.error();
  Result<const Array*> transl = part(params, group, "transl", frames, 3, path);
  if (!transl) return transl.error();
  m->layout = ModelKind::SmplX;
  if (Status s = motion_detail::allocateFrames(frames, 55, path, m); !s) return s;
  m->translation.resize(frames);
  for (int64_t f = 0; f < frames; ++f) {
    motion_detail::putAxisAngle((*root)->data.data() + 3 * f, 1, 0, &m->frames[f]);
    motion_detail::putAxisAngle((*pose)->data.data() + 63 * f, 21, 1, &m->frames[f]);
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>((*transl)->data.data() + 3 * f);
  }
  Result<bool> left = putAbsoluteHand(params, group, "left_hand_pose", 25, path, m);
  if (!left) return left.error();
  Result<bool> right = putAbsoluteHand(params, group, "right_hand_pose", 40, path, m);
  if (!right) return right.error();
  const Eigen::VectorXd zeros = Eigen::VectorXd::Zero(45);  // a side without poses: hands_mean
  if (!*left) m->hands.left.assign(frames, zeros);
  if (!*right) m->hands.right.assign(frames, zeros);
  if (*left || *right)
    m->notes.push_back(std::string("hands from ") +
                       (*left && *right ? "'left_hand_pose' and 'right_hand_pose'"
                        : *left         ? "'left_hand_pose' (the right hand at hands_mean)"
                                        : "'right_hand_pose' (the left hand at hands_mean)") +
                       ": absolute finger rotations (flat_hand_mean=True, as Mano2Smpl-X merges "
                       "them)");
  else
    m->notes.push_back(
        "hands at the model's hands_mean (GVHMR's SMPL-X: no hand pose, flat_hand_mean=False)");
  m->hands.rest_without_mean =
      "the model has no hands_mean: GVHMR's hands (its SMPL-X's mean hand) stay at rest";
  return Status();
}

Status decodeGvhmr(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  Result<bool> world = readsWorld(root, in);
  if (!world) return world.error();
  const std::string group = *world ? "smpl_params_global" : "smpl_params_incam";
  const DataNode& params = *root.get(group);
  Motion m;
  if (Status s = decodePoses(params, group, in.path, &m); !s) return s;
  if (const Array* b = params.leaf("betas")) {  // (L,10); any width is padded or cut later
    const int64_t width = b->shape.size() == 2 ? b->shape[1] : 10;
    Result<const Array*> betas =
        part(params, group, "betas", static_cast<int64_t>(m.frames.size()), width, in.path);
    if (!betas) return betas.error();
    if (Status s = video_rows::putBetas(**betas, in.path, "betas", "", &m); !s) return s;
  }
  m.notes.insert(m.notes.begin(), "read as GVHMR output (SMPL-X; one person)");
  if (*world) {
    m.world = MotionWorld::Y;
    m.notes.push_back("world frame ('smpl_params_global'; Y up)");
  } else {
    m.world = MotionWorld::CameraYDown;
    m.world_why = "GVHMR's 'smpl_params_incam' is in the camera frame";
  }
  m.fps = 0.0;
  out->tracks.push_back(std::move(m));
  return Status();
}

}  // namespace

const MotionLayout& gvhmrLayout() {
  static const MotionLayout row{"gvhmr",
                                "GVHMR output (smpl_params_global / smpl_params_incam)",
                                kTorchFile | kPickleFile | kJoblibFile,
                                matchesGvhmr,
                                {"smpl_params_global", "smpl_params_incam"},
                                decodeGvhmr};
  return row;
}

}  // namespace smpl
