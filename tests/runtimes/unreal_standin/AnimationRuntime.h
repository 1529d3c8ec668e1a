// Stand-in for Unreal's AnimationRuntime.h (see CoreMinimal.h).
#pragma once

#include "BonePose.h"

struct FAnimationRuntime {
  static FTransform GetComponentSpaceTransformRefPose(const FReferenceSkeleton& Ref, int32 Bone) {
    FQuat q = Ref.RefPose.at(size_t(Bone)).Rotation;
    for (int32 p = Ref.Parents[size_t(Bone)]; p >= 0; p = Ref.Parents[size_t(p)])
      q = Ref.RefPose[size_t(p)].Rotation * q;
    return FTransform(q);
  }
};
