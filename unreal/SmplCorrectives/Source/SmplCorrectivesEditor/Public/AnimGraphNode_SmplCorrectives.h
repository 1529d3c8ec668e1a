// UAnimGraphNode_SmplCorrectives: the Animation Blueprint graph node of
// FAnimNode_SmplCorrectives ("SMPL Correctives", category "SMPL").
#pragma once

#include "AnimGraphNode_Base.h"
#include "AnimNode_SmplCorrectives.h"
#include "CoreMinimal.h"
#include "AnimGraphNode_SmplCorrectives.generated.h"

UCLASS()
class SMPLCORRECTIVESEDITOR_API UAnimGraphNode_SmplCorrectives : public UAnimGraphNode_Base
{
	GENERATED_BODY()

public:
	UPROPERTY(EditAnywhere, Category = Settings)
	FAnimNode_SmplCorrectives Node;

	virtual FText GetNodeTitle(ENodeTitleType::Type TitleType) const override;
	virtual FText GetTooltipText() const override;
	virtual FString GetNodeCategory() const override;
	virtual FLinearColor GetNodeTitleColor() const override;
};
