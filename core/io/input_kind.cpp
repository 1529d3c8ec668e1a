// The sniffer and the kinds' bounds (see the header for why each bound).
#include "core/io/input_kind.h"

#include <cstring>

namespace smpl {
namespace {

constexpr uint64_t kMiB = 1ull << 20;

bool startsWith(const uint8_t* head, size_t size, const char* magic, size_t n) {
  return size >= n && std::memcmp(head, magic, n) == 0;
}

bool looksLikeJson(const uint8_t* head, size_t size) {
  size_t i = startsWith(head, size, "\xEF\xBB\xBF", 3) ? 3 : 0;
  while (i < size && (head[i] == ' ' || head[i] == '\t' || head[i] == '\n' || head[i] == '\r')) ++i;
  return i < size && (head[i] == '{' || head[i] == '[');
}

}  // namespace

FileFormat sniffFormat(const uint8_t* head, size_t size) {
  if (size > kSniffBytes) size = kSniffBytes;
  if (size == 0) return FileFormat::Unknown;
  if (startsWith(head, size, "PK\x03\x04", 4) || startsWith(head, size, "PK\x05\x06", 4))
    return FileFormat::Zip;
  if (startsWith(head, size, "\x93NUMPY", 6)) return FileFormat::Npy;
  if (head[0] == 0x80 || head[0] == '(' || head[0] == '}' || head[0] == ']')
    return FileFormat::Pickle;
  if (looksLikeJson(head, size)) return FileFormat::Json;
  if (std::memchr(head, 0, size) == nullptr) return FileFormat::Text;
  return FileFormat::Unknown;
}

const char* formatName(FileFormat format) {
  switch (format) {
    case FileFormat::Zip:
      return ".npz (zip)";
    case FileFormat::Npy:
      return ".npy";
    case FileFormat::Pickle:
      return ".pkl (pickle)";
    case FileFormat::Json:
      return "JSON";
    case FileFormat::Text:
      return "text";
    default:
      return "unknown";
  }
}

const AcceptedFormat* acceptedFormat(const InputKind& kind, FileFormat format) {
  for (const AcceptedFormat& a : kind.formats)
    if (a.format == format) return &a;
  if (format == FileFormat::Json) return acceptedFormat(kind, FileFormat::Text);
  return nullptr;
}

const InputKind kModelInput = {
    "model file", {{FileFormat::Zip, kNoSizeBound}, {FileFormat::Pickle, kNoSizeBound}}, false};
const InputKind kMotionInput = {"motion file",
                                {{FileFormat::Zip, kNoSizeBound},
                                 {FileFormat::Npy, 1024 * kMiB},
                                 {FileFormat::Pickle, 1024 * kMiB},
                                 {FileFormat::Json, 256 * kMiB},
                                 {FileFormat::Text, 256 * kMiB},
                                 {FileFormat::Unknown, kNoSizeBound}},
                                true};
const InputKind kUvObjInput = {"UV file", {{FileFormat::Text, 256 * kMiB}}, true};
const InputKind kUvNpyInput = {"UV file", {{FileFormat::Npy, 256 * kMiB}}, true};
const InputKind kBetasInput = {
    "betas file",
    {{FileFormat::Npy, 256 * kMiB}, {FileFormat::Zip, 256 * kMiB}, {FileFormat::Json, 64 * kMiB}},
    true};
const InputKind kDmplInput = {"DMPL basis", {{FileFormat::Zip, 1024 * kMiB}}, false};
const InputKind kNpyInput = {".npy file", {{FileFormat::Npy, 1024 * kMiB}}, true};

}  // namespace smpl
