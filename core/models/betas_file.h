// --betas-file: shape coefficients from a file, read by the same npy/npz
// readers as the models and motions (core/io) or as JSON, then range-checked
// where they enter (validate_inputs.h: finite, |value| <= 1000).
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

// Betas from .npy, .npz (key 'betas'; other members are not read) or .json
// ([..] or {"betas": [..]}). Arrays of shape (T,B) follow core/models/betas_rows.h:
// identical rows -> that row; differing rows -> their mean, and `note` (if
// given) says so with the largest deviation. Errors are one line naming the
// file ("b.json: not valid JSON", "b.npy: 'betas'[1] is nan; expected ...").
Result<std::vector<double>> readBetasFile(const std::string& path, std::string* note = nullptr);

}  // namespace smpl
