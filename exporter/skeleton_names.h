// The bone names of --skeleton-names: one row per SMPL-family joint (SMPL,
// SMPL-H, SMPL-X; core/joint_names.h) with the name that joint's bone gets on
// an Adobe Mixamo rig and on the Unreal Engine 5 Mannequin (SK_Mannequin), so
// that those engines' retarget presets find the bones by name. Plain data;
// docs/retargeting.md shows the table, why the spine maps as it does and the
// public sources the names were checked against.
#pragma once

#include <string>
#include <vector>

#include "exporter/asset.h"
#include "exporter/export_options.h"

namespace smpl {

// One joint's names. nullptr: the rig has no bone for the joint (Mixamo has
// no SMPL hand-end joint, no jaw, no eyes; the UE5 Mannequin has no jaw or
// eyes), and the bone keeps the model's name: no bone is invented.
struct SkeletonNameRow {
  const char* joint;   // the model's joint name ("left_hip")
  const char* mixamo;  // "mixamorig:LeftUpLeg" or nullptr
  const char* ue5;     // "thigh_l" or nullptr
};

// Every row, in SMPL-X-then-SMPL order (57: 22 body, SMPL's two hand ends,
// jaw, two eyes, 30 finger joints).
const std::vector<SkeletonNameRow>& skeletonNameTable();

// "smpl", "mixamo" or "ue5" (the --skeleton-names value, recorded in the metadata).
const char* skeletonNamesName(SkeletonNames names);

// The bone name of model joint `joint` under `names`: the table's entry, or
// `joint` itself (Smpl, a joint the rig has no bone for, a name not in the
// table such as --root-bone's `root`).
std::string boneNameOf(const std::string& joint, SkeletonNames names);

// Renames `asset`'s bones (Skeleton::names) for `names` and records the
// choice and the model's names in asset->metadata (skeleton_names,
// model_joint_names) for the sidecar. Smpl: nothing changes. Morph target
// names (pose_<joint>_<rc>) keep the model's names: the runtime drivers map
// them to bones through the metadata.
void renameSkeleton(SkeletonNames names, Asset* asset);

}  // namespace smpl
