// Motion -> AnimationClip for the model being exported: map the motion's joint
// layout onto the model by joint name (e.g. SMPL-H motion on SMPL: the body
// joints; fingers are dropped), cut frames, resample (slerp / lerp), convert a
// Z-up capture world (AMASS) to the exported Y-up, and compute the corrective
// morph weights of every frame from the rotations, so the baked file plays
// back with no runtime script.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/motions/motion.h"
#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

// The motion world's up axis (--up); the output is always Y-up.
//   Auto  what the motion's layout says (Motion::world): Z for AMASS, -y for
//         the camera frames of video methods, else Y
//   Z     a Z-up world, turned -90 degrees about x
//   NegY  a camera frame (OpenCV: y down, z forward), turned upright by one
//         half turn about x: (x, y, z) -> (x, -y, -z), about the world origin
//         (camera-relative translations stay camera-relative)
enum class UpAxis { Auto, Y, Z, NegY };

// The rotation that turns a motion's world Y-up (identity for Y).
Eigen::Matrix3d worldTurn(UpAxis up, MotionWorld world);

// The request checks the ranges (request/check_request.h); here
// they are preconditions: fps >= 0, and a frame range outside a motion is
// that motion's export error.
struct AnimationOptions {
  std::optional<double> fps;  // output rate (fps); none keeps the motion's rate
  int first_frame = 0;        // --frames A:B, source frames, B exclusive
  int end_frame = -1;         // -1: to the end
  UpAxis up = UpAxis::Auto;
  bool in_place = false;  // --root-motion in-place: drop horizontal root motion
};

struct MotionMapping {
  std::vector<int> source_of_joint;  // model joint -> motion joint, -1 = rest rotation
  std::vector<std::string> dropped;  // motion joints the model lacks
  std::vector<std::string> missing;  // model joints the motion lacks
};

Result<MotionMapping> mapMotion(const BodyModel& model, const Motion& motion,
                                const std::string& context);

// Progress callback: fraction in [0, 1].
using Progress = std::function<void(double)>;

// `asset` supplies the rest joints and the morph target order. The clip
// records the joints the mapping dropped (AnimationClip::dropped_joints).
// `release` (null, or &motion when the caller needs no frame of it again):
// each decoded frame is freed once no later output frame reads it
// (Motion::frames keeps its length; its entries become empty), so a long
// clip peaks at about its tracks rather than its frames plus its tracks.
Result<AnimationClip> bakeAnimation(const BodyModel& model, const Asset& asset,
                                    const Motion& motion, const AnimationOptions& options,
                                    const std::string& context, const Progress& progress = nullptr,
                                    Motion* release = nullptr);

}  // namespace smpl
