// The pickle-based containers today's tools write, read as DataNode trees
// (core/data_node.h) by the same data-only VM as model files (pickle.h):
// nothing named in a file is ever imported or called.
//   plain pickles   pickle.dump of dicts, lists, numpy arrays (4D-Humans,
//                   AIST++, fits), collections.defaultdict (WHAM's results)
//   joblib          joblib.dump: each array a NumpyArrayWrapper whose bytes
//                   follow its BUILD opcode (pickle_joblib.cpp); zlib- or
//                   gzip-compressed files (compress=3, '.z', '.gz') inflated
//                   first; bz2, lzma, xz and lz4 refused by name
//   torch .pt       torch.save's zip (torch >= 1.6): <root>/data.pkl whose
//                   tensors name storages <root>/data/<key> (pickle_torch.cpp)
//   object .npy     np.save of a dict or of an object array (TRAM, MDM)
//   torch tensors   in plain pickles, joblib files and object .npy (not in
//                   model files or a .pt): _rebuild_tensor_v2 whose storage
//                   is torch.storage._load_from_bytes(b), b torch's legacy
//                   serialization of one storage, read by the same VM one
//                   level deep (pickle_torch_legacy.cpp); the tensors as in a
//                   .pt. Malformed bytes (truncated, a count beyond them or
//                   not the declared numel, wrong magic or version, a view, a
//                   nested _load_from_bytes) are one-line errors: "x.npy:
//                   torch.storage._load_from_bytes: storage '0' has 6
//                   elements of 4 bytes, but only 19 bytes follow"
// Conversion (pickle_tree.cpp): dict -> Dict (str/bytes keys as text, int
// keys as decimal text, other keys skipped); list/tuple -> an Array leaf when
// it is a rectangular nest of numbers, else a List (an empty one too) whose
// unconvertible elements are None; ndarray, tensor, scipy sparse, chumpy Ch,
// str, bytes and numbers -> Array leaves (numbers widened to double, C
// order; text as `strings`); None and other objects -> None. Nesting deeper
// than 32 levels is an error; a cycle ends in None.
// Memory: everything built is charged before it is made, against the memory
// budget and against PickleLimits' expansion bound (so a small file that
// repeats one shared object is refused instead of growing to gigabytes).
// Errors are one line naming `context` and, where known, the byte offset,
// the key path ("at [0]['smpl'][1]") or the archive member.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/data_node.h"
#include "core/io/pickle/pickle.h"
#include "core/result.h"

namespace smpl {

// A plain pickle or an uncompressed joblib file (protocols 0-5).
Result<DataNode> parsePickleTree(const uint8_t* data, size_t size, const std::string& context,
                                 const PickleLimits& limits = PickleLimits());

// How a joblib file is compressed, from its first bytes (joblib's own
// _detect_compressor prefixes, joblib/compressor.py): zlib 0x78, gzip 1f 8b,
// bz2 "BZ", xz fd 37 7a 58 5a, lzma 5d 00, lz4 04 22 4d 18; "ZF" is the
// zfile of joblib < 0.9.3. None: not compressed.
enum class JoblibCompression { None, Zlib, Gzip, Bz2, Lzma, Xz, Lz4, Zfile };
JoblibCompression joblibCompression(const uint8_t* data, size_t size);

// A joblib file, compressed or not: zlib and gzip are inflated (the inflated
// size charged to the memory budget as it grows; a bomb ends with the budget
// error), then read as parsePickleTree. bz2/lzma/xz/lz4 and zfiles are
// refused with what to do, e.g. "a bz2-compressed joblib file: decompress it
// first (python3 -c "import joblib; joblib.dump(joblib.load('FILE'),
// 'FILE', compress=('zlib', 3))"), or save it with compress=('zlib', 3)".
Result<DataNode> parseJoblib(const uint8_t* data, size_t size, const std::string& context,
                             const PickleLimits& limits = PickleLimits());

// torch.save's zip archive: members <root>/data.pkl (the pickle),
// <root>/data/<key> (raw storage bytes), <root>/byteorder ("little" or
// "big"; absent: little). Tensors (_rebuild_tensor_v2/_v3, _rebuild_tensor,
// nn.Parameter) become Array leaves of their dtype (float64/32/16, bfloat16,
// int8-64, uint8-64, bool; dtype strings as numpy's, "bfloat16" for that),
// with any strides and storage offset, every index checked against the
// storage size; storages shared by several tensors are read once per tensor.
// Refused: TorchScript archives (constants.pkl), missing storage records,
// complex and quantized storages, any global but torch's tensor rebuild
// functions and the pickle.h allow-list (named in the error).
Result<DataNode> parseTorchZip(const uint8_t* data, size_t size, const std::string& context,
                               const PickleLimits& limits = PickleLimits());

// An .npy image: a numeric or text array -> one Array leaf (parseNpy); an
// object array (np.save with allow_pickle) -> its 0-d element as a tree (an
// np.save'd dict -> that Dict), or, for n-d, one leaf when every element is
// a number (or every one a string), else Lists nested as its shape.
Result<DataNode> parseNpyTree(const uint8_t* data, size_t size, const std::string& context,
                              const PickleLimits& limits = PickleLimits());

// True for torch's legacy (non-zip) serialization: a pickle of the magic
// number 0x1950a86a20f9469cfc6c first (torch < 1.6, or
// _use_new_zipfile_serialization=False). Such files are refused with
// kLegacyTorchMessage.
bool isLegacyTorchFile(const uint8_t* data, size_t size);
inline constexpr const char* kLegacyTorchMessage =
    "a legacy torch file: re-save it with torch.save(obj, f) in torch >= 1.6";
// joblib < 0.9.3's compressed "zfile" (JoblibCompression::Zfile).
inline constexpr const char* kZfileMessage =
    "a joblib file from joblib < 0.9.3 (zfile 'ZF' header): load it with joblib and dump it "
    "again with a current joblib";

}  // namespace smpl
