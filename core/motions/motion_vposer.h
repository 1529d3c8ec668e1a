// VPoser latents (SMPLify-X with use_vposer: `pose_embedding`; HuMoR /
// SLAHMR optimizer state: `latent_pose` (B,T,32); `latent`): a 32-d code of
// VPoser's decoder, not rotations. Recognised so that the file is refused
// with what to do instead of "a shape file" or an unknown layout:
//   "<file>: a VPoser latent: decode it with VPoser first ('latent_pose' has
//    32 values per frame)"
// A file that also carries a decoded pose (`pose_body`, `body_pose`, `poses`)
// is read by that pose's layout instead (SLAHMR's results). SMPLify-X's
// `body_pose` of 32 values is refused by the fit layout (motion_fit.h).
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

// The table row: a refusal (decode always fails with the message above).
const MotionLayout& vposerLayout();

}  // namespace smpl
