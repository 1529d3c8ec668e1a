// The uncooked-only module of the SMPL Correctives plugin (the AnimGraph node).
#include "Modules/ModuleManager.h"

IMPLEMENT_MODULE(FDefaultModuleImpl, SmplCorrectivesEditor)
