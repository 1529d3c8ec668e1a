#include "core/motions/motion_vposer.h"

#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

const char* const kLatentKeys[] = {"latent_pose", "pose_embedding", "latent"};

bool matchesVposer(const DataNode& root) {
  for (const char* decoded : {"poses", "pose_body", "body_pose", "bodyPose"})
    if (motion_detail::has(root, decoded)) return false;
  for (const char* key : kLatentKeys)
    if (motion_detail::has(root, key)) return true;
  return false;
}

Status refuseLatent(const DataNode& root, const LayoutInput& in, MotionSet*) {
  for (const char* key : kLatentKeys) {
    const Array* a = motion_detail::find(root, key);
    if (!a && !motion_detail::has(root, key)) continue;
    const std::string what = a && !a->shape.empty() && a->shape.back() == 32
                                 ? "'" + std::string(key) + "' has 32 values per frame"
                                 : "'" + std::string(key) + "'";
    return makeError(in.path + ": a VPoser latent: decode it with VPoser first (" + what + ")");
  }
  return makeError(in.path + ": a VPoser latent: decode it with VPoser first");
}

}  // namespace

const MotionLayout& vposerLayout() {
  static const MotionLayout row{
      "vposer",      "VPoser latent (refused: decode it first)",  kAnyContainer,
      matchesVposer, {"latent_pose", "pose_embedding", "latent"}, refuseLatent};
  return row;
}

}  // namespace smpl
