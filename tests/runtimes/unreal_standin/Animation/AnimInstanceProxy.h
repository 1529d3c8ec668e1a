// Stand-in for Unreal's Animation/AnimInstanceProxy.h (see CoreMinimal.h).
#pragma once

#include "BonePose.h"

class FAnimInstanceProxy {
 public:
  FBoneContainer Required;
  const FBoneContainer& GetRequiredBones() const { return Required; }
};
