// parseJoblib: a joblib.dump file, compressed or not. joblib.load picks the
// decompressor from the first bytes (_detect_compressor in
// joblib/numpy_pickle_utils.py, prefixes in joblib/compressor.py) and reads
// one pickle from the decompressed stream; zlib and gzip are inflated here
// (core/io/inflate.h), the other compressors are refused with what to do.
#include <cstring>

#include "core/io/inflate.h"
#include "core/io/pickle/pickle_internal.h"
#include "core/io/pickle/pickle_tree.h"

namespace smpl {
namespace {

bool startsWith(const uint8_t* data, size_t size, const char* prefix, size_t n) {
  return size >= n && std::memcmp(data, prefix, n) == 0;
}

// What to tell the user about a compressor we do not read.
std::string refusal(const std::string& compressor) {
  return (compressor == "bz2" ? "a " : "an ") + compressor +
         "-compressed joblib file: decompress it first (python3 -c \"import joblib; "
         "joblib.dump(joblib.load('FILE'), 'FILE', compress=('zlib', 3))\"), or save it with "
         "compress=('zlib', 3)";
}

}  // namespace

JoblibCompression joblibCompression(const uint8_t* data, size_t size) {
  if (startsWith(data, size, "ZF", 2)) return JoblibCompression::Zfile;
  // zlib: CMF 0x78 (deflate, 32 KiB window) and a header checksum that zlib requires.
  if (size >= 2 && data[0] == 0x78 && ((data[0] << 8) | data[1]) % 31 == 0)
    return JoblibCompression::Zlib;
  if (startsWith(data, size, "\x1f\x8b", 2)) return JoblibCompression::Gzip;
  if (startsWith(data, size, "BZ", 2)) return JoblibCompression::Bz2;
  if (startsWith(data, size, "\xfd\x37\x7a\x58\x5a", 5)) return JoblibCompression::Xz;
  if (startsWith(data, size, "\x5d\x00", 2)) return JoblibCompression::Lzma;
  if (startsWith(data, size, "\x04\x22\x4d\x18", 4)) return JoblibCompression::Lz4;
  return JoblibCompression::None;
}

Result<DataNode> parseJoblib(const uint8_t* data, size_t size, const std::string& context,
                             const PickleLimits& limits) {
  StreamFormat format = StreamFormat::Zlib;
  switch (joblibCompression(data, size)) {
    case JoblibCompression::None:
      return parsePickleTree(data, size, context, limits);
    case JoblibCompression::Zlib:
      break;
    case JoblibCompression::Gzip:
      format = StreamFormat::Gzip;
      break;
    case JoblibCompression::Bz2:
      return makeError(context + ": " + refusal("bz2"));
    case JoblibCompression::Lzma:
      return makeError(context + ": " + refusal("lzma"));
    case JoblibCompression::Xz:
      return makeError(context + ": " + refusal("xz"));
    case JoblibCompression::Lz4:
      return makeError(context + ": " + refusal("lz4"));
    case JoblibCompression::Zfile:
      return makeError(context + ": " + kZfileMessage);
  }
  // The pickle and its arrays cannot need more than the input-scaled bound
  // (pickle::heapByteLimit), so nothing past it is inflated: a small file
  // whose stream goes on for gigabytes costs at most the bound.
  const uint64_t bound = pickle::heapByteLimit(limits, size);
  Result<InflatedBytes> inflated = inflateStream(data, size, format, context, bound, true);
  if (!inflated) return inflated.error();
  Result<DataNode> tree =
      parsePickleTree(inflated->data.data(), inflated->data.size(), context, limits);
  // Stopped at the bound: if the pickle ended before it, what follows is
  // bytes joblib.load never reads either (it stops at STOP) and the tree
  // stands; if the pickle needed more, the stream is past what it may need.
  if (tree || inflated->complete) return tree;
  return makeError(context + ": compressed stream inflates past " + formatBytes(bound) +
                   " before its pickle ends (the input-scaled bound: " +
                   std::to_string(limits.expansion) + " x the file's size, at least " +
                   formatBytes(limits.expansion_floor) + "; --memory-limit caps it further)");
}

}  // namespace smpl
