// Stand-in for Unreal's Modules/ModuleManager.h (see CoreMinimal.h).
#pragma once

class FDefaultModuleImpl {};
#define IMPLEMENT_MODULE(Impl, Name) [[maybe_unused]] static Impl Name##Module;
