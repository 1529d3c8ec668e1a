// Stand-in for Unreal's Animation/AnimNodeBase.h (see CoreMinimal.h).
#pragma once

#include <functional>
#include <map>

#include "BonePose.h"
#include "CoreMinimal.h"

class FAnimInstanceProxy;

struct FAnimationInitializeContext {};
struct FAnimationUpdateContext {};
struct FAnimationCacheBonesContext {
  FAnimInstanceProxy* AnimInstanceProxy = nullptr;
};

/// Curves by name (Unreal 5.3+: FBlendedCurve::Set(FName, float)).
struct FBlendedCurve {
  std::map<std::string, float> Values;
  void Set(const FName& Name, float Value) { Values[Name.ToString().Std()] = Value; }
};

struct FPoseContext {
  FCompactPose Pose;
  FBlendedCurve Curve;
};

struct FNodeDebugData {
  std::vector<std::string> Items;
  template <class Node>
  FString GetNodeName(Node*) {
    return FString("SmplCorrectives");
  }
  void AddDebugItem(const FString& Line) { Items.push_back(Line.Std()); }
};

/// The input pose: the test sets Produce to write the pose it wants.
struct FPoseLink {
  std::function<void(FPoseContext&)> Produce;
  void Initialize(const FAnimationInitializeContext&) {}
  void CacheBones(const FAnimationCacheBonesContext&) {}
  void Update(const FAnimationUpdateContext&) {}
  void Evaluate(FPoseContext& Output) {
    if (Produce) Produce(Output);
  }
  void GatherDebugData(FNodeDebugData&) {}
};

struct FExposedValueHandler {
  void Execute(const FAnimationUpdateContext&) const {}
};

struct FAnimNode_Base {
  virtual ~FAnimNode_Base() = default;
  virtual void Initialize_AnyThread(const FAnimationInitializeContext&) {}
  virtual void CacheBones_AnyThread(const FAnimationCacheBonesContext&) {}
  virtual void Update_AnyThread(const FAnimationUpdateContext&) {}
  virtual void Evaluate_AnyThread(FPoseContext&) {}
  virtual void GatherDebugData(FNodeDebugData&) {}
  const FExposedValueHandler& GetEvaluateGraphExposedInputs() const {
    static FExposedValueHandler h;
    return h;
  }
};
