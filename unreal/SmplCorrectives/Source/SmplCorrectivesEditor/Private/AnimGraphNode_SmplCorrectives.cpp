// Editor-side presentation of the SMPL Correctives node. Not compiled against
// Unreal Engine in this repository's CI (unreal/README.md).
#include "AnimGraphNode_SmplCorrectives.h"

#define LOCTEXT_NAMESPACE "SmplCorrectives"

FText UAnimGraphNode_SmplCorrectives::GetNodeTitle(ENodeTitleType::Type /*TitleType*/) const
{
	return LOCTEXT("Title", "SMPL Correctives");
}

FText UAnimGraphNode_SmplCorrectives::GetTooltipText() const
{
	return LOCTEXT("Tooltip",
		"Drives the pose-corrective morph targets of an smpl-export body from its bones "
		"(place after the last node that changes the pose).");
}

FString UAnimGraphNode_SmplCorrectives::GetNodeCategory() const
{
	return TEXT("SMPL");
}

FLinearColor UAnimGraphNode_SmplCorrectives::GetNodeTitleColor() const
{
	return FLinearColor(0.2f, 0.4f, 0.8f);
}

#undef LOCTEXT_NAMESPACE
