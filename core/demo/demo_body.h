// The built-in demo body (`--model builtin`): generated in code, deterministic,
// with SMPL's structure (24 joints, canonical names and tree, 10 meaningful
// shape directions, 207 pose correctives) so that every command works on a
// machine with no licensed model file.
#pragma once

#include "core/body_model.h"

namespace smpl {

// Same bytes every call; a few thousand vertices; passes validateModel().
const BodyModel& demoBody();

}  // namespace smpl
