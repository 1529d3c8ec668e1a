// Runtime module: the animation node (FAnimNode_SmplCorrectives) and the
// engine-independent core headers (Public/SmplCorrectives*.h, tested in CI).
using UnrealBuildTool;

public class SmplCorrectives : ModuleRules
{
	public SmplCorrectives(ReadOnlyTargetRules Target) : base(Target)
	{
		PCHUsage = PCHUsageMode.UseExplicitOrSharedPCHs;
		CppStandard = CppStandardVersion.Cpp17;
		PublicDependencyModuleNames.AddRange(new string[] { "Core", "CoreUObject", "Engine" });
	}
}
