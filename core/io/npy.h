// .npy reader: numpy's array format, versions 1.0-3.0. Little/big endian,
// C and Fortran order, f2/f4/f8, i1-i8, u1-u8, b1, 0-d arrays, and unicode /
// byte strings ('<U6', '|S6', e.g. AMASS's `gender`). Every size is validated
// against the buffer before it is read; object arrays ('|O') are refused here
// (core/io/pickle's parseObjectNpy decodes them when a caller needs one).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/array.h"
#include "core/io/input_kind.h"
#include "core/result.h"

namespace smpl {

// Parse an .npy image. `context` names the source in errors ("beta.npy",
// "model.npz/shapedirs.npy").
Result<Array> parseNpy(const uint8_t* data, size_t size, const std::string& context);

// The header of an .npy image, without its data: what lazy readers need to
// tell an object array ('|O', whose data is a pickle) from a numeric one, or
// to report a member's shape without decoding it.
struct NpyHeaderInfo {
  std::string descr;  // e.g. "<f8", "|O"
  bool fortran_order = false;
  std::vector<int64_t> shape;
  size_t data_offset = 0;  // first byte after the header
};
Result<NpyHeaderInfo> parseNpyHeader(const uint8_t* data, size_t size, const std::string& context);

// True for descr "|O" (also "<O"/">O"): numpy writes these as a pickle.
bool isObjectDescr(const std::string& descr);

// Read a whole .npy file from disk. The file must start with the .npy magic
// and stay within its kind's size bound (input_kind.h; kNpyInput: 1 GiB),
// checked before it is read (readFileBytes(path, kind)).
Result<Array> readNpyFile(const std::string& path, const InputKind& kind = kNpyInput);

}  // namespace smpl
