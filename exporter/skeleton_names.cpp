#include "exporter/skeleton_names.h"

namespace smpl {

const std::vector<SkeletonNameRow>& skeletonNameTable() {
  // Mixamo: mixamorig:<Bone>, "Left"/"Right" prefixes, fingers 1..3 from the
  // palm. UE5 Mannequin: lower case, _l/_r suffixes, fingers _01.._03 (the
  // metacarpals index/middle/ring/pinky_metacarpal_* have no SMPL joint and
  // stay out). SMPL's three spine joints on UE5's five: see docs/retargeting.md.
  static const std::vector<SkeletonNameRow> rows = {
      {"pelvis", "mixamorig:Hips", "pelvis"},
      {"left_hip", "mixamorig:LeftUpLeg", "thigh_l"},
      {"right_hip", "mixamorig:RightUpLeg", "thigh_r"},
      {"spine1", "mixamorig:Spine", "spine_01"},
      {"left_knee", "mixamorig:LeftLeg", "calf_l"},
      {"right_knee", "mixamorig:RightLeg", "calf_r"},
      {"spine2", "mixamorig:Spine1", "spine_03"},
      {"left_ankle", "mixamorig:LeftFoot", "foot_l"},
      {"right_ankle", "mixamorig:RightFoot", "foot_r"},
      {"spine3", "mixamorig:Spine2", "spine_05"},
      {"left_foot", "mixamorig:LeftToeBase", "ball_l"},
      {"right_foot", "mixamorig:RightToeBase", "ball_r"},
      {"neck", "mixamorig:Neck", "neck_01"},
      {"left_collar", "mixamorig:LeftShoulder", "clavicle_l"},
      {"right_collar", "mixamorig:RightShoulder", "clavicle_r"},
      {"head", "mixamorig:Head", "head"},
      {"left_shoulder", "mixamorig:LeftArm", "upperarm_l"},
      {"right_shoulder", "mixamorig:RightArm", "upperarm_r"},
      {"left_elbow", "mixamorig:LeftForeArm", "lowerarm_l"},
      {"right_elbow", "mixamorig:RightForeArm", "lowerarm_r"},
      {"left_wrist", "mixamorig:LeftHand", "hand_l"},
      {"right_wrist", "mixamorig:RightHand", "hand_r"},
      // SMPL (24 joints) only: a hand's end without fingers; neither rig has it.
      {"left_hand", nullptr, nullptr},
      {"right_hand", nullptr, nullptr},
      // SMPL-X only: neither rig has a jaw or eye bones.
      {"jaw", nullptr, nullptr},
      {"left_eye_smplhf", nullptr, nullptr},
      {"right_eye_smplhf", nullptr, nullptr},
      // SMPL-H and SMPL-X fingers.
      {"left_index1", "mixamorig:LeftHandIndex1", "index_01_l"},
      {"left_index2", "mixamorig:LeftHandIndex2", "index_02_l"},
      {"left_index3", "mixamorig:LeftHandIndex3", "index_03_l"},
      {"left_middle1", "mixamorig:LeftHandMiddle1", "middle_01_l"},
      {"left_middle2", "mixamorig:LeftHandMiddle2", "middle_02_l"},
      {"left_middle3", "mixamorig:LeftHandMiddle3", "middle_03_l"},
      {"left_pinky1", "mixamorig:LeftHandPinky1", "pinky_01_l"},
      {"left_pinky2", "mixamorig:LeftHandPinky2", "pinky_02_l"},
      {"left_pinky3", "mixamorig:LeftHandPinky3", "pinky_03_l"},
      {"left_ring1", "mixamorig:LeftHandRing1", "ring_01_l"},
      {"left_ring2", "mixamorig:LeftHandRing2", "ring_02_l"},
      {"left_ring3", "mixamorig:LeftHandRing3", "ring_03_l"},
      {"left_thumb1", "mixamorig:LeftHandThumb1", "thumb_01_l"},
      {"left_thumb2", "mixamorig:LeftHandThumb2", "thumb_02_l"},
      {"left_thumb3", "mixamorig:LeftHandThumb3", "thumb_03_l"},
      {"right_index1", "mixamorig:RightHandIndex1", "index_01_r"},
      {"right_index2", "mixamorig:RightHandIndex2", "index_02_r"},
      {"right_index3", "mixamorig:RightHandIndex3", "index_03_r"},
      {"right_middle1", "mixamorig:RightHandMiddle1", "middle_01_r"},
      {"right_middle2", "mixamorig:RightHandMiddle2", "middle_02_r"},
      {"right_middle3", "mixamorig:RightHandMiddle3", "middle_03_r"},
      {"right_pinky1", "mixamorig:RightHandPinky1", "pinky_01_r"},
      {"right_pinky2", "mixamorig:RightHandPinky2", "pinky_02_r"},
      {"right_pinky3", "mixamorig:RightHandPinky3", "pinky_03_r"},
      {"right_ring1", "mixamorig:RightHandRing1", "ring_01_r"},
      {"right_ring2", "mixamorig:RightHandRing2", "ring_02_r"},
      {"right_ring3", "mixamorig:RightHandRing3", "ring_03_r"},
      {"right_thumb1", "mixamorig:RightHandThumb1", "thumb_01_r"},
      {"right_thumb2", "mixamorig:RightHandThumb2", "thumb_02_r"},
      {"right_thumb3", "mixamorig:RightHandThumb3", "thumb_03_r"},
  };
  return rows;
}

const char* skeletonNamesName(SkeletonNames names) {
  switch (names) {
    case SkeletonNames::Mixamo:
      return "mixamo";
    case SkeletonNames::Ue5:
      return "ue5";
    case SkeletonNames::Smpl:
      break;
  }
  return "smpl";
}

std::string boneNameOf(const std::string& joint, SkeletonNames names) {
  if (names == SkeletonNames::Smpl) return joint;
  for (const SkeletonNameRow& row : skeletonNameTable()) {
    if (joint != row.joint) continue;
    const char* bone = names == SkeletonNames::Mixamo ? row.mixamo : row.ue5;
    return bone ? bone : joint;
  }
  return joint;
}

void renameSkeleton(SkeletonNames names, Asset* asset) {
  if (names == SkeletonNames::Smpl) return;
  asset->metadata.skeleton_names = skeletonNamesName(names);
  asset->metadata.model_joint_names = asset->skeleton.names;
  for (std::string& name : asset->skeleton.names) name = boneNameOf(name, names);
}

}  // namespace smpl
