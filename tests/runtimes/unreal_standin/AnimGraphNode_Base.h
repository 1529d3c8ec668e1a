// Stand-in for Unreal's AnimGraphNode_Base.h (editor; see CoreMinimal.h).
#pragma once

#include "CoreMinimal.h"

struct FText {
  std::string Text;
};
#define LOCTEXT(Key, Text) \
  FText { Text }
struct FLinearColor {
  FLinearColor(float r, float g, float b, float a = 1.f) : R(r), G(g), B(b), A(a) {}
  float R, G, B, A;
};
namespace ENodeTitleType {
enum Type { FullTitle, MenuTitle };
}
class UAnimGraphNode_Base {
 public:
  virtual ~UAnimGraphNode_Base() = default;
  virtual FText GetNodeTitle(ENodeTitleType::Type) const { return FText(); }
  virtual FText GetTooltipText() const { return FText(); }
  virtual FString GetNodeCategory() const { return FString(); }
  virtual FLinearColor GetNodeTitleColor() const { return FLinearColor(0, 0, 0); }
};
