// UVs from a pair of numpy files, as some tools and repositories ship them:
// <stem>_uv.npy (U,2) texture coordinates (or <stem>_vt.npy) and <stem>_ft.npy
// (F,3) per-corner UV indices, one row per model face (the model's own `f`
// gives the vertex of each corner). Give either file; its partner is found by
// replacing the suffix. Seams are split as for an OBJ (uv_split.h).
#pragma once

#include <string>

#include "core/body_model.h"
#include "core/models/uv_split.h"
#include "core/result.h"

namespace smpl {

// Errors: "body_ft.npy: index 812 out of range; expected [0,800) ('body_uv.npy' has 800 rows)".
Result<UvLayout> loadUvNumpyPair(const std::string& path, const BodyModel& model);

// The two paths of the pair named by `path` (coords first); error if `path`
// does not end in _uv.npy, _vt.npy or _ft.npy or the partner does not exist.
Result<std::pair<std::string, std::string>> uvNumpyPairPaths(const std::string& path);

}  // namespace smpl
