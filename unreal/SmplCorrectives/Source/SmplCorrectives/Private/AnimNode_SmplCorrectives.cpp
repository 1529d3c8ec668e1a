// FAnimNode_SmplCorrectives: engine glue only (see the header). Not compiled
// against Unreal Engine in this repository's CI (unreal/README.md).
#include "AnimNode_SmplCorrectives.h"

#include "Animation/AnimInstanceProxy.h"
#include "AnimationRuntime.h"
#include "BonePose.h"
#include "Misc/FileHelper.h"
#include "Misc/Paths.h"
#include "SmplCorrectivesMetadata.h"

DEFINE_LOG_CATEGORY_STATIC(LogSmplCorrectives, Log, All);

namespace
{
smpl_correctives::Mat3 RotationOf(const FTransform& Transform)
{
	const FQuat Q = Transform.GetRotation();
	return smpl_correctives::fromQuaternion(Q.X, Q.Y, Q.Z, Q.W);
}
}  // namespace

smpl_correctives::Mat3 FAnimNode_SmplCorrectives::Axes() const
{
	if (AxisPreset == ESmplAxisPreset::Identity) return smpl_correctives::identity();
	if (AxisPreset == ESmplAxisPreset::Custom)  // columns: Unreal coordinates of the model axes
		return {CustomAxisX.X, CustomAxisY.X, CustomAxisZ.X, CustomAxisX.Y, CustomAxisY.Y, CustomAxisZ.Y,
				CustomAxisX.Z, CustomAxisY.Z, CustomAxisZ.Z};
	return smpl_correctives::unrealFbxAxes();
}

void FAnimNode_SmplCorrectives::Initialize_AnyThread(const FAnimationInitializeContext& Context)
{
	FAnimNode_Base::Initialize_AnyThread(Context);
	Source.Initialize(Context);
	FString Text = MetadataJson;
	Problem = FString();
	if (Text.IsEmpty() && !MetadataFile.FilePath.IsEmpty())
	{
		const FString Path = FPaths::ConvertRelativePathToFull(FPaths::ProjectDir(), MetadataFile.FilePath);
		if (!FFileHelper::LoadFileToString(Text, *Path)) Problem = Path + TEXT(": cannot read the metadata");
	}
	Layout = smpl_correctives::Layout();
	Evaluator = smpl_correctives::Evaluator();  // unbound until CacheBones binds the new layout
	if (!Text.IsEmpty())
	{
		const std::string Error = smpl_correctives::parseLayout(std::string(TCHAR_TO_UTF8(*Text)), &Layout);
		Problem = Error.empty() ? FString() : FString(UTF8_TO_TCHAR(Error.c_str()));
	}
	else if (Problem.IsEmpty())
	{
		Problem = TEXT("no metadata: set MetadataJson or MetadataFile (the FBX's .smpl.json sidecar)");
	}
	if (!Problem.IsEmpty()) UE_LOG(LogSmplCorrectives, Warning, TEXT("SMPL Correctives: %s"), *Problem);
}

void FAnimNode_SmplCorrectives::CacheBones_AnyThread(const FAnimationCacheBonesContext& Context)
{
	Source.CacheBones(Context);
	if (!Problem.IsEmpty() && Layout.joint_names.empty()) return;
	const FBoneContainer& Required = Context.AnimInstanceProxy->GetRequiredBones();
	const FReferenceSkeleton& Reference = Required.GetReferenceSkeleton();
	std::vector<std::string> Names;
	for (int32 Bone = 0; Bone < Reference.GetNum(); ++Bone)
		Names.push_back(std::string(TCHAR_TO_UTF8(*Reference.GetBoneName(Bone).ToString())));
	Bones = smpl_correctives::matchBones(Layout, Names);
	const std::string Error = smpl_correctives::bindSkeleton(&Evaluator, Layout, Axes(), Bones,
		[&Reference](int Bone) { return RotationOf(FAnimationRuntime::GetComponentSpaceTransformRefPose(Reference, Bone)); });
	Problem = Error.empty() ? FString() : FString(UTF8_TO_TCHAR(Error.c_str()));
	CurveNames.Reset();
	for (size_t i = 0; i < Evaluator.targetCount(); ++i)
		CurveNames.Add(FName(UTF8_TO_TCHAR(Evaluator.targetName(i).c_str())));
	// A joint stripped by LOD has no compact index: it is then read as rigid with its parent.
	for (size_t k = 0; k < Bones.bone_of_joint.size(); ++k)
		if (!Bones.missing[k] && !Required.MakeCompactPoseIndex(FMeshPoseBoneIndex(Bones.bone_of_joint[k])).IsValid())
			Bones.missing[k] = true;
}

void FAnimNode_SmplCorrectives::Update_AnyThread(const FAnimationUpdateContext& Context)
{
	GetEvaluateGraphExposedInputs().Execute(Context);
	Source.Update(Context);
}

void FAnimNode_SmplCorrectives::Evaluate_AnyThread(FPoseContext& Output)
{
	Source.Evaluate(Output);
	if (!Evaluator.bound() || Alpha <= 0.f) return;
	FCSPose<FCompactPose> ComponentPose;
	ComponentPose.InitPose(Output.Pose);
	const FBoneContainer& Required = Output.Pose.GetBoneContainer();
	smpl_correctives::driveFrame(Evaluator, Bones,
		[&](int Bone) {
			const FCompactPoseBoneIndex Index = Required.MakeCompactPoseIndex(FMeshPoseBoneIndex(Bone));
			return RotationOf(ComponentPose.GetComponentSpaceTransform(Index));
		},
		[&](size_t Curve, const std::string&, double Weight) {
			Output.Curve.Set(CurveNames[int32(Curve)], Alpha * float(Weight));  // UE 5.3+ FBlendedCurve::Set
		},
		&Scratch);
}

void FAnimNode_SmplCorrectives::GatherDebugData(FNodeDebugData& DebugData)
{
	FString Line = DebugData.GetNodeName(this);
	Line += Problem.IsEmpty() ? FString::Printf(TEXT("(%d joints, %d curves)"), Bones.found, CurveNames.Num())
							  : FString::Printf(TEXT("(%s)"), *Problem);
	DebugData.AddDebugItem(Line);
	Source.GatherDebugData(DebugData);
}
