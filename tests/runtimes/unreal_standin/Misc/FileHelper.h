// Stand-in for Unreal's Misc/FileHelper.h (see CoreMinimal.h).
#pragma once

#include <fstream>
#include <iterator>

#include "CoreMinimal.h"

struct FFileHelper {
  static bool LoadFileToString(FString& Result, const TCHAR* Path) {
    std::ifstream in(Path, std::ios::binary);
    if (!in) return false;
    Result =
        FString(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
    return true;
  }
};
