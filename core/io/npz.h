// .npz reader: a zip of .npy files. Keys lose their ".npy" suffix, as numpy's
// np.load does. Errors name the archive and the member:
// "model.npz/shapedirs.npy: truncated data: expected 1653600 bytes, found 1000".
#pragma once

#include <cstdint>
#include <string>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

Result<ArrayDict> parseNpz(const uint8_t* data, size_t size, const std::string& context);
Result<ArrayDict> readNpzFile(const std::string& path);

}  // namespace smpl
