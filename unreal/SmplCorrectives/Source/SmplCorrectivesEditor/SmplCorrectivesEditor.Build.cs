// Uncooked-only module: the Animation Blueprint graph node (UAnimGraphNode_SmplCorrectives).
using UnrealBuildTool;

public class SmplCorrectivesEditor : ModuleRules
{
	public SmplCorrectivesEditor(ReadOnlyTargetRules Target) : base(Target)
	{
		PCHUsage = PCHUsageMode.UseExplicitOrSharedPCHs;
		PublicDependencyModuleNames.AddRange(new string[] { "Core", "CoreUObject", "Engine", "SmplCorrectives" });
		PrivateDependencyModuleNames.AddRange(new string[] { "AnimGraph", "BlueprintGraph" });
	}
}
