// The last check before any writer, called by every writer (writers/) and by
// exportAsset: the asset's structure (validate_structure.h: shapes, indices,
// one root, increasing key times, normals) and then every number a writer
// serialises is finite, and every number stored as float32 fits a float32. Inputs are
// validated where they enter; this catches what arithmetic makes of them
// (a huge but finite translation that overflows float, a NaN from a bad
// division) so that NaN and Inf never reach an output file.
#pragma once

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

// Checks, in this order: skeleton rest_local/rest_world (K x 3, metres);
// mesh positions, normals, uvs, skin weights (V x 3, V x 3, V x 2, V x M);
// morph target deltas (V x 3) and rest weights; per animation fps, key times
// (seconds), rotations (quaternion w,x,y,z), root translations (metres) and
// morph weights (T x targets); metadata numbers (betas, expression, corrective
// scale/offset, corrective basis matrix/scale/offset); then
// validateAssetStructure (its rules and errors in validate_structure.h).
// Error (first problem only): "<what> is not finite (nan)" or "... exceeds
// the float32 range (1e+39)", e.g.
//   "morph target pose_l_knee_00 vertex 12 is not finite (nan)"
//   "animation walk frame 3 root translation exceeds the float32 range (1e+39)".
Status validateAsset(const Asset& asset);

}  // namespace smpl
