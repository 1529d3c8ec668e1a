// A file given in the wrong role is named with the option that takes it:
// a motion or a shape file given as --model, an exported glTF given as
// --model. Asked only after the model loader refused the file, so a real
// model's own errors ("'posedirs' has shape ...") are never replaced; the
// other direction (a model given as --motion) is core/motions'
// unmatchedMessage.
#pragma once

#include <string>

#include "core/result.h"

namespace smpl {

// `refused` (the model loader's error for `path`) replaced by
//   "<path>: a motion file (the amass layout), not a body model: give it as
//    --motion, and the model authors' .npz or .pkl (SMPL_NEUTRAL.npz, ...)
//    as --model"
// when the motion readers recognise the file (probeMotionFile: a layout row
// matches), "<path>: a shape file (betas only), not a body model: give it as
// --betas-file ..." for a shape file, and "<path>: a binary glTF (GLB), an
// exported file, not a body model ..." for a GLB; else `refused` unchanged.
Error modelRoleError(const std::string& path, const Error& refused);

}  // namespace smpl
