// numpy element data, shared by the .npy reader (core/npy.cpp) and the
// pickle reader's ndarray payloads (core/pickle_ndarray.cpp). Both containers
// hold the same thing: raw elements in the dtype's byte order, in C or Fortran
// order, described by a descr such as '<f8', '|b1' or '>U6'. Decoding them in
// one place keeps the two readers agreeing on which dtypes exist, how half
// floats, signed integers and UTF-32 strings are read, and how hostile sizes
// are refused (every size is checked before anything is allocated).
//
//   Result<NumpyDtype> t = parseNumpyDescr("<f8", "beta.npy");
//   Result<Array> a = decodeNumpyArray(bytes, n, *t, {3, 4}, false, "beta.npy");
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

// An element type: f2/f4/f8, i1-i8, u1-u8, b1, S<n> (bytes), U<n> (UTF-32).
struct NumpyDtype {
  char kind = 0;        // 'f', 'i', 'u', 'b', 'S', 'U'
  size_t itemsize = 0;  // bytes per element ('U': 4 per character)
  bool big_endian = false;
  std::string descr;  // as written, e.g. "<f8"; becomes Array::dtype
};

// Parse a descr: byte order ('<', '>', '|', '=' for this host), kind, count
// (characters for 'U', bytes otherwise). Object, structured/void and other
// kinds are refused; `context` names the source in errors ("model.npz/f.npy").
Result<NumpyDtype> parseNumpyDescr(const std::string& descr, const std::string& context);

// Bytes that an array of `shape` occupies, or an error if that overflows.
// Dimensions are checked even when one of them is 0, so Array::size() of any
// array decoded with this shape cannot overflow either.
Result<size_t> numpyByteCount(const NumpyDtype& dtype, const std::vector<int64_t>& shape,
                              const std::string& context);

// Decode exactly `size` bytes of elements (an error if that is not what
// `shape` needs) into an Array in C order: numbers widened to double in
// `data`, strings as UTF-8 without numpy's trailing NUL padding in `strings`.
Result<Array> decodeNumpyArray(const uint8_t* data, size_t size, const NumpyDtype& dtype,
                               const std::vector<int64_t>& shape, bool fortran_order,
                               const std::string& context);

}  // namespace smpl
