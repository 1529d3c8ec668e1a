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
  const Eigen::VectorXd zeros = Eigen::VectorXd::Zero(45);  // hands at hands_mean
  for (int64_t f = 0; f < frames; ++f) {
    motion_detail::putAxisAngle((*root)->data.data() + 3 * f, 1, 0, &m->frames[f]);
    motion_detail::putAxisAngle((*pose)->data.data() + 63 * f, 21, 1, &m->frames[f]);
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>((*transl)->data.data() + 3 * f);
    m->hands.left.push_back(zeros);
    m->hands.right.push_back(zeros);
  }
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
  m.notes.push_back("read as GVHMR output (SMPL-X; one person)");
  m.notes.push_back(
      "hands at the model's hands_mean (GVHMR's SMPL-X: no hand pose, flat_hand_mean=False)");
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
