// --betas-file: shape coefficients from a file.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

// Betas from .npy, .npz (key 'betas') or .json ([..] or {"betas": [..]}).
// Arrays of shape (T,B) follow core/load/betas_rows.h: identical rows -> that
// row; differing rows -> their mean, and `note` (if given) says so with the
// largest deviation. Errors name the file.
Result<std::vector<double>> readBetasFile(const std::string& path, std::string* note = nullptr);

}  // namespace smpl
