// Where the exported body stands: --origin floor puts its lowest point on the
// floor (y = 0 of the Y-up file) and --root-bone adds a `root` joint on the
// floor below the pelvis that carries the ground-plane motion (what Unreal
// and Unity call root motion). Both change only where things are, never the
// posed shape: one constant shift of every position, and a root bone whose
// translation the pelvis gives back. exportAsset (export_asset.h) applies
// them to the finished asset after the motions are baked, so every writer and
// the BVH writer's skeleton and tracks (Asset::skeleton, AnimationClip) carry them.
#pragma once

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

// The lowest y (metres, Y-up file frame) of the body as the file plays it.
// Without animations: the rest mesh as shown, positions + sum_n
// rest_weight_n * deltas_n * peak_n. With animations: over every frame of
// every clip, the posed mesh the way the file skins it: morphed vertices
// q_v = positions_v + sum_n w_n(t) deltas_n,v peak_n (clip morph weights),
// linear blend skinning with the asset's M influences and joint transforms
// G_k from the clip's rotations, root translation and joint translations
// (docs/file-contract.md). The morph part is evaluated exactly only for the
// vertices that a bound |a . delta| <= max_n |w_n| sum_n |d_n,v| peak_n cannot
// rule out (a convex blend of rotations has norm <= 1), so a long clip costs
// about one skinning pass per frame. Precondition: a valid asset with a mesh
// (validateAssetStructure); a skeleton-only asset has no vertices (returns
// +infinity).
double lowestPoint(const Asset& asset);

// Adds dy metres to the y of every position: rest mesh, rest joints (world
// and the root's local offset), each clip's root translation and joint 0's
// translation track. Morph deltas and rotations are unchanged. Records
// placement.origin "floor" and floor_offset += dy.
void shiftAssetUp(Asset* asset, double dy);

// --root-bone: inserts joint 0 `root` (parent -1, identity rotation) at
// (J_0.x, 0, J_0.z) below the pelvis; the model's joints move to 1..K in
// model order (parents + 1, the pelvis' parent is root), the pelvis' rest
// offset becomes (0, J_0.y, 0) and skin joint indices move by one. Per frame,
// with p(t) the pelvis' world position (the clip's root translation): root
// translation (p.x, 0, p.z), pelvis local translation (0, p.y, 0) (a
// joint_translations track), rotations unchanged, so every posed vertex is
// unchanged. Precondition: no root bone yet, the asset valid.
void addRootBone(Asset* asset);

}  // namespace smpl
