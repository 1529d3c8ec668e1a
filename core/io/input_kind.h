// What an input file of each kind looks like, so that a file that is not what
// it claims is refused from its first bytes and its size before it is read
// whole: a 3 GB sparse file given as --uv, --betas-file or --motion costs a
// 4 KiB read and an fstat, not 3 GB of memory, and /dev/stdin is not a model.
//
// A kind lists the formats it accepts, each with a size bound: a regular file
// larger than the bound is refused unread; a pipe (where a kind allows pipes)
// is read up to the bound and then refused. The bounds are far above any real
// file of that kind (README "Details"): an SMPL-X UV layout is 0.2 MB as .npy
// (bound 256 MiB), betas a few KB (256 MiB, 64 MiB as JSON), an AMASS motion a
// few MB (pickle 1 GiB, JSON 256 MiB: parsed JSON takes about ten times its
// text). Models and .npz archives are memory-mapped and read lazily, so only
// their first bytes are checked; the memory budget bounds what is decoded.
//
// Used through core/io/file_io.h:
//   Result<FileFormat> f = checkInputFile(path, kModelInput);   // sniff + size, nothing read
//   Result<std::vector<uint8_t>> b = readFileBytes(path, kUvObjInput);  // sniffed, bounded
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace smpl {

// What the first bytes of a file show.
enum class FileFormat {
  Unknown,  // none of the below (a sparse file's zeros, a GLB, compressed data, ...)
  Zip,      // "PK\3\4" or "PK\5\6" (an empty archive): .npz, SMPLCodec .smpl
  Npy,      // "\x93NUMPY"
  Pickle,   // protocol 2+ (0x80), or a protocol 0/1 opening ('(' MARK, '}' '{}', ']' '[]')
  Json,     // optional UTF-8 byte order mark and blanks, then '{' or '['
  Text,     // no NUL byte in the first kSniffBytes (an OBJ file); JSON is text too
};

constexpr size_t kSniffBytes = 4096;

// The format of a file that starts with `head` (its first min(size,
// kSniffBytes) bytes). An empty head is Unknown.
FileFormat sniffFormat(const uint8_t* head, size_t size);

// ".npz (zip)", ".npy", ".pkl (pickle)", "JSON", "text": for errors.
const char* formatName(FileFormat format);

struct AcceptedFormat {
  FileFormat format;
  uint64_t max_bytes;  // larger files of this format are refused
};

struct InputKind {
  const char* what;                     // "UV file", "model file": "not a <what>"
  std::vector<AcceptedFormat> formats;  // Text accepts a file that sniffs as JSON
  bool pipes = true;                    // false: regular files only (mapped readers)
};

// The accepted entry for `format`, or nullptr.
const AcceptedFormat* acceptedFormat(const InputKind& kind, FileFormat format);

constexpr uint64_t kNoSizeBound = ~0ull;  // mapped and read lazily: the memory budget decides

// --model FILE: .npz or .pkl, regular files only (mapped).
extern const InputKind kModelInput;
// --motion FILE / --motion-dir entries: zips (.npz, .smpl, torch .pt: lazy, no
// bound), .npy and pickles/joblib (1 GiB), JSON and other text (256 MiB); any
// other first bytes (compressed joblib, or none of them) are left to the
// container sniffer (core/io/tree/data_tree.h), which names what it reads.
// The motion reader (core/motions/motion_read.cpp) calls, before it maps the file,
//   Result<FileFormat> f = checkInputFile(path, kMotionInput);
extern const InputKind kMotionInput;
// --uv FILE.obj: text, 256 MiB.
extern const InputKind kUvObjInput;
// --uv <stem>_uv.npy / _ft.npy: .npy, 256 MiB each.
extern const InputKind kUvNpyInput;
// --betas-file: .npy or .npz (256 MiB), .json (64 MiB).
extern const InputKind kBetasInput;
// --dmpl FILE: .npz, 1 GiB, regular files only.
extern const InputKind kDmplInput;
// readNpyFile's default: any .npy, 1 GiB.
extern const InputKind kNpyInput;

}  // namespace smpl
