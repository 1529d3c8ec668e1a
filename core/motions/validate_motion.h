// The range checks of a loaded motion, where it enters (loadMotion): the
// bounds of core/models/validate_inputs.h (frame rate, translations, betas,
// rotation matrices, the frame change, expression values) applied to a whole
// Motion. Here, not in validate_inputs, because Motion is a motions/ type and
// models/ never includes motions/.
#pragma once

#include <string>

#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

// A loaded motion: frame rate, translations, betas and rotation matrices (the
// latter re-orthonormalised within the tolerance, hence the pointer).
Status checkMotionValues(Motion* motion, const std::string& path);

}  // namespace smpl
