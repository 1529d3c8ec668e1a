// .npy reader: numpy's array format, versions 1.0-3.0. Little/big endian,
// C and Fortran order, f2/f4/f8, i1-i8, u1-u8, b1, 0-d arrays, and unicode /
// byte strings ('<U6', '|S6', e.g. AMASS's `gender`). Every size is validated
// against the buffer before it is read; object arrays ('|O') are refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

// Parse an .npy image. `context` names the source in errors ("beta.npy",
// "model.npz/shapedirs.npy").
Result<Array> parseNpy(const uint8_t* data, size_t size, const std::string& context);

// Read a whole .npy file from disk.
Result<Array> readNpyFile(const std::string& path);

}  // namespace smpl
