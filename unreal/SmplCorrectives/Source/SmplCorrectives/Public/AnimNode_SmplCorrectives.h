// FAnimNode_SmplCorrectives: an Animation Blueprint node that drives the
// pose-corrective morph targets of an smpl-export body from its bones.
//
// Each frame it evaluates its input pose, reads the component-space rotation of
// every bone named after a model joint, computes the weights with the C++ core
// (SmplCorrectivesCore.h: the robust formula of docs/file-contract.md and the
// metadata's weight mapping) and writes one curve per corrective morph target
// (curve name = morph target name). All math is in the engine-independent
// headers that CI tests; this node only moves data (see unreal/README.md for
// what was and was not compiled against the engine).
#pragma once

#include "Animation/AnimNodeBase.h"
#include "CoreMinimal.h"
#include "SmplCorrectivesAdapter.h"
#include "SmplCorrectivesCore.h"
#include "AnimNode_SmplCorrectives.generated.h"

/// C: how the importer mapped the model's axes (+Y up, right-handed) to Unreal's.
UENUM(BlueprintType)
enum class ESmplAxisPreset : uint8
{
	/// Unreal's FBX importer with default axis options: model (x, y, z) -> Unreal (x, z, y).
	UnrealFbxImport,
	/// Model axes are Unreal's axes (e.g. an asset re-exported in Unreal's frame).
	Identity,
	/// CustomAxisX/Y/Z below: the Unreal coordinates of the model's x, y and z axes.
	Custom
};

USTRUCT(BlueprintInternalUseOnly)
struct SMPLCORRECTIVES_API FAnimNode_SmplCorrectives : public FAnimNode_Base
{
	GENERATED_BODY()

	UPROPERTY(EditAnywhere, BlueprintReadWrite, Category = Links)
	FPoseLink Source;

	/// The sidecar <file>.fbx.smpl.json pasted as text (stored in the Animation
	/// Blueprint, so it also works in packaged builds). Wins over MetadataFile.
	UPROPERTY(EditAnywhere, Category = Metadata, meta = (MultiLine = true))
	FString MetadataJson;

	/// The sidecar file, read when the node initialises (editor and development
	/// builds; relative paths are relative to the project folder).
	UPROPERTY(EditAnywhere, Category = Metadata, meta = (FilePathFilter = "json"))
	FFilePath MetadataFile;

	UPROPERTY(EditAnywhere, Category = Axes)
	ESmplAxisPreset AxisPreset = ESmplAxisPreset::UnrealFbxImport;

	UPROPERTY(EditAnywhere, Category = Axes, meta = (EditCondition = "AxisPreset == ESmplAxisPreset::Custom"))
	FVector CustomAxisX = FVector(1, 0, 0);
	UPROPERTY(EditAnywhere, Category = Axes, meta = (EditCondition = "AxisPreset == ESmplAxisPreset::Custom"))
	FVector CustomAxisY = FVector(0, 0, 1);
	UPROPERTY(EditAnywhere, Category = Axes, meta = (EditCondition = "AxisPreset == ESmplAxisPreset::Custom"))
	FVector CustomAxisZ = FVector(0, 1, 0);

	/// Multiplies every weight (0 turns the correctives off).
	UPROPERTY(EditAnywhere, BlueprintReadWrite, Category = Settings, meta = (PinShownByDefault, ClampMin = "0"))
	float Alpha = 1.0f;

	// FAnimNode_Base
	virtual void Initialize_AnyThread(const FAnimationInitializeContext& Context) override;
	virtual void CacheBones_AnyThread(const FAnimationCacheBonesContext& Context) override;
	virtual void Update_AnyThread(const FAnimationUpdateContext& Context) override;
	virtual void Evaluate_AnyThread(FPoseContext& Output) override;
	virtual void GatherDebugData(FNodeDebugData& DebugData) override;

private:
	smpl_correctives::Mat3 Axes() const;

	smpl_correctives::Layout Layout;
	smpl_correctives::Evaluator Evaluator;
	smpl_correctives::BoneMap Bones;
	std::vector<smpl_correctives::Mat3> Scratch;
	TArray<FName> CurveNames;  // per Evaluator output, FName made once
	FString Problem;           // shown in the debug data and logged once
};
