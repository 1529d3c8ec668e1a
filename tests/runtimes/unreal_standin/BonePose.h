// Stand-in for Unreal's BonePose.h / ReferenceSkeleton.h / BoneContainer.h
// (see CoreMinimal.h): bones with parents, local rotations, component space
// composed as Unreal does (child component = parent component * local).
#pragma once

#include "CoreMinimal.h"

struct FMeshPoseBoneIndex {
  explicit FMeshPoseBoneIndex(int32 i) : Index(i) {}
  int32 Index;
};

struct FCompactPoseBoneIndex {
  explicit FCompactPoseBoneIndex(int32 i) : Index(i) {}
  bool IsValid() const { return Index >= 0; }
  int32 Index;
};

struct FReferenceSkeleton {
  std::vector<std::string> Names;
  std::vector<int32> Parents;       // -1 for the root
  std::vector<FTransform> RefPose;  // local
  int32 GetNum() const { return int32(Names.size()); }
  FName GetBoneName(int32 i) const { return FName(Names.at(size_t(i)).c_str()); }
};

struct FBoneContainer {
  FReferenceSkeleton Reference;
  std::vector<bool> Stripped;  // bones removed by LOD: no compact index
  const FReferenceSkeleton& GetReferenceSkeleton() const { return Reference; }
  FCompactPoseBoneIndex MakeCompactPoseIndex(const FMeshPoseBoneIndex& Mesh) const {
    bool gone = size_t(Mesh.Index) < Stripped.size() && Stripped[size_t(Mesh.Index)];
    return FCompactPoseBoneIndex(gone ? -1 : Mesh.Index);
  }
};

struct FCompactPose {
  const FBoneContainer* Bones = nullptr;
  std::vector<FTransform> Local;
  const FBoneContainer& GetBoneContainer() const { return *Bones; }
};

template <class Pose>
struct FCSPose {
  std::vector<FTransform> Component;
  void InitPose(const Pose& pose) {
    const FReferenceSkeleton& ref = pose.GetBoneContainer().GetReferenceSkeleton();
    Component.resize(pose.Local.size());
    for (size_t b = 0; b < Component.size(); ++b) {
      int32 p = ref.Parents[b];
      Component[b] = FTransform(p < 0 ? pose.Local[b].Rotation
                                      : Component[size_t(p)].Rotation * pose.Local[b].Rotation);
    }
  }
  const FTransform& GetComponentSpaceTransform(const FCompactPoseBoneIndex& i) const {
    return Component.at(size_t(i.Index));
  }
};
