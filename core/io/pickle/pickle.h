// Data-only unpickler for model files (.pkl): protocols 0-5, Python 2 and 3
// writers. It rebuilds exactly the objects model files contain and refuses
// every other global with an error naming it; it never executes anything.
//   numpy arrays    numpy.core.multiarray._reconstruct + BUILD state,
//                   numpy.core.numeric._frombuffer (protocol 5), numpy.dtype,
//                   payloads as bytes, py2 str, or _codecs.encode(latin-1 text)
//                   (also numpy._core.* module paths of numpy 2)
//   scipy sparse    csc/csr matrices under any module path (scipy.sparse.csc,
//                   scipy.sparse._csc, ...) -> dense Array
//   chumpy Ch       chumpy.ch.Ch / chumpy.Ch objects -> their array state
//   containers      dict, list, tuple, str, bytes, int, float, bool, None
// The top level must be a dict; entries whose value is an array-like
// (ndarray, sparse, Ch, list of numbers, string) become Arrays, the rest are
// dropped. The readers of tools' containers (joblib, torch .pt, nested
// values as trees) are in pickle_tree.h; they extend this allow-list only
// for their own containers.
#pragma once

#include <cstdint>
#include <string>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

struct PickleLimits {
  uint64_t max_memo = 1u << 20;         // memo entries
  uint64_t max_stack_depth = 1u << 16;  // nesting
  uint64_t max_total_bytes = 4ull << 30;
  // What the objects built from one input (and the arrays converted from
  // them) may take in all: max(expansion_floor, expansion x the input's
  // bytes), and never more than max_total_bytes. Building from the data
  // itself stays far below 256 bytes per input byte (one opcode byte makes at
  // most one object; uint8 arrays widen 8x to doubles, 16x with their copy);
  // beyond it the objects can only come from sharing: memo references that
  // repeat one list or array thousands of times. So a 16 KiB pickle is
  // refused at 64 MiB instead of reaching gigabytes first.
  uint64_t expansion = 256;
  uint64_t expansion_floor = 64ull << 20;
};

Result<ArrayDict> parsePickle(const uint8_t* data, size_t size, const std::string& context,
                              const PickleLimits& limits = PickleLimits());
Result<ArrayDict> readPickleFile(const std::string& path);

// An .npy image of dtype '|O' (what np.save/np.savez write for object arrays,
// with allow_pickle): its data is a pickle of the array, decoded here by the
// same data-only VM. Elements may be numbers, strings, array-likes (for 0-d
// arrays) or, for a 0-d array, a dict of string -> number, which becomes an
// Array with `keys` (core/array.h). Anything else is an error naming
// `context`; nothing is executed.
Result<Array> parseObjectNpy(const uint8_t* data, size_t size, const std::string& context,
                             const PickleLimits& limits = PickleLimits());

}  // namespace smpl
