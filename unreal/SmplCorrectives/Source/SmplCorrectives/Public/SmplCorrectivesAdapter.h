// SmplCorrectivesAdapter.h: what the Unreal animation node does with the core,
// written against plain callables instead of engine types (header-only, C++17
// standard library only), so CI runs it (tests/unit/unreal/runtime_adapter_test.cpp)
// with a stand-in skeleton. FAnimNode_SmplCorrectives passes lambdas over
// FCSPose / FBlendedCurve; nothing else in the node computes anything.
//
//   BoneMap bones = matchBones(layout, bone_names);                // once per skeleton
//   bindSkeleton(&ev, layout, axes, bones, restRotationOfBone);    // once
//   driveFrame(ev, bones, rotationOfBone, setCurve, &scratch);     // every frame
#pragma once

#include <string>
#include <vector>

#include "SmplCorrectivesCore.h"

namespace smpl_correctives {

/// Model joint k -> engine bone index (-1: no such bone; the joint is then
/// rigid with its parent, see Evaluator::bind).
struct BoneMap {
  std::vector<int> bone_of_joint;  ///< K entries
  std::vector<bool> missing;       ///< K entries, bone_of_joint[k] < 0
  int found = 0;                   ///< joints with a bone
};

/// A bone name without an importer's namespace or path prefix: "ns:pelvis",
/// "Armature|pelvis" -> "pelvis".
inline std::string shortBoneName(const std::string& name) {
  size_t cut = name.find_last_of(":|");
  return cut == std::string::npos ? name : name.substr(cut + 1);
}

/// Joints matched to bones by name: exact, else the short name; SMPL-X's
/// left_eye_smplhf / right_eye_smplhf also match an older left_eye / right_eye.
/// With the metadata's bone_names (--skeleton-names) joint k's bone is the one
/// named bone_names[k] ("thigh_l"; "mixamorig:Hips" also as "Hips").
inline BoneMap matchBones(const Layout& layout, const std::vector<std::string>& bone_names) {
  BoneMap map;
  for (size_t k = 0; k < layout.joint_names.size(); ++k) {
    const bool renamed = layout.bone_names.size() == layout.joint_names.size();
    const std::string& joint = renamed ? layout.bone_names[k] : layout.joint_names[k];
    int hit = -1;
    std::string alias = joint.size() > 7 && joint.compare(joint.size() - 7, 7, "_smplhf") == 0
                            ? joint.substr(0, joint.size() - 7)
                            : std::string();
    for (int pass = 0; pass < 3 && hit < 0; ++pass)
      for (size_t b = 0; b < bone_names.size() && hit < 0; ++b) {
        const std::string name = pass == 0 ? bone_names[b] : shortBoneName(bone_names[b]);
        if (name == joint || (pass == 2 && !alias.empty() && name == alias) ||
            (pass == 2 && renamed && name == shortBoneName(joint)))
          hit = int(b);
      }
    map.bone_of_joint.push_back(hit);
    map.missing.push_back(hit < 0);
    map.found += hit >= 0;
  }
  return map;
}

/// Binds the evaluator to the skeleton's reference (bind) pose.
/// rest_rotation_of(bone index) -> Mat3: the bone's reference-pose rotation in
/// component space. Returns an error line or empty (no joint found is an error).
template <class RestRotationOf>
std::string bindSkeleton(Evaluator* ev, const Layout& layout, const Mat3& axes,
                         const BoneMap& bones, RestRotationOf rest_rotation_of) {
  if (bones.found == 0) return "skeleton: no bone is named after a joint of the metadata";
  std::vector<Mat3> rest(layout.joint_names.size(), identity());
  for (size_t k = 0; k < rest.size(); ++k)
    if (!bones.missing[k]) rest[k] = rest_rotation_of(bones.bone_of_joint[k]);
  return ev->bind(layout, axes, rest, bones.missing);
}

/// One frame: reads every matched bone's component-space rotation
/// (rotation_of(bone index) -> Mat3), evaluates, and calls
/// set_curve(i, target name, weight) for every corrective target i (metadata
/// order, then the basis targets).
/// `scratch` keeps the K rotations between frames (no allocation after the first).
template <class RotationOf, class SetCurve>
void driveFrame(Evaluator& ev, const BoneMap& bones, RotationOf rotation_of, SetCurve set_curve,
                std::vector<Mat3>* scratch) {
  if (!ev.bound()) return;
  scratch->resize(bones.bone_of_joint.size(), identity());
  for (size_t k = 0; k < scratch->size(); ++k)
    if (!bones.missing[k]) (*scratch)[k] = rotation_of(bones.bone_of_joint[k]);
  ev.evaluate(*scratch);
  for (size_t i = 0; i < ev.targetCount(); ++i) set_curve(i, ev.targetName(i), ev.weights()[i]);
}

}  // namespace smpl_correctives
