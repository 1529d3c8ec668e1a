// The runtime module of the SMPL Correctives plugin (no startup work).
#include "Modules/ModuleManager.h"

IMPLEMENT_MODULE(FDefaultModuleImpl, SmplCorrectives)
