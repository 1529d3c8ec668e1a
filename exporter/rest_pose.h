// --rest-pose a: the skeleton's rest re-expressed as an A-pose (the arms 45
// degrees down from the T-pose's horizontal), the rest retargeting tools for
// Mixamo and UE5 characters expect, with every key re-expressed so the
// animation moves the joints exactly as before.
//
// The A-pose rotates joint left_shoulder by Rz(-45 deg) and right_shoulder by
// Rz(+45 deg) about their rest joints (model axes: +X is the body's left,
// +Y up, so both arms swing down); its world rotations G_k are Rz(-45 deg)
// for left_shoulder and every joint below it, Rz(+45 deg) for the right
// side, identity elsewhere. Then, with J the rest joints, p = parent(k):
//
//   A rest joint    P_k = P_p + G_p (J_k - J_p)     (P_root = J_root)
//   rest offset     P_k - P_p                      (Skeleton::rest_local)
//   local rotation  R'_k(t) = G_p R_k(t) G_k^-1     (every clip, every frame)
//   joint track     t'_k(t) = G_p t_k(t)           (joint_translations)
//
// so each joint's world position W'_k(t) = W_k(t) for every frame (by
// induction: W'_k = W'_p + (world rot'_p) G_p (J_k - J_p) with
// world rot'_p = world rot_p G_p^-1). The rest rotations of the file stay
// identity: only the offsets and the keys change.
//
// Only for skeleton-only assets (BVH): a skinned mesh bound at the A pose
// deforms differently under linear blend skinning (a vertex weighted across
// the collar and the shoulder moves by up to about a centimetre), so the
// request refuses --rest-pose a for formats with a mesh.
#pragma once

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

constexpr double kAPoseDegrees = 45.0;  // arms below horizontal at the A rest

// Re-expresses `asset` (model joint names, before any renaming) at the A
// rest, as above, and records "a" in asset->metadata.rest_pose. Errors: a
// skeleton without left_shoulder or right_shoulder (MANO), an asset with a
// mesh.
Status applyARestPose(Asset* asset);

}  // namespace smpl
