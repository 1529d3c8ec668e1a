// Stand-in for Unreal's Misc/Paths.h (see CoreMinimal.h).
#pragma once

#include "CoreMinimal.h"

struct FPaths {
  static FString ProjectDir() { return FString(""); }
  static FString ConvertRelativePathToFull(const FString& Base, const FString& Path) {
    return Path.Std().empty() || Path.Std()[0] == '/' ? Path : Base + Path;
  }
};
