// SHA-256 of bytes and files through the platform's implementation
// (sha256_digest.h): a well-kept implementation rather than our own. Files are
// hashed in 1 MiB chunks, so memory stays flat whatever the output size.
#include "core/io/sha256.h"

#include <vector>

#include "core/io/sha256_digest.h"
#include "core/os/files.h"

namespace smpl {
namespace {

// The digest as 64 lowercase hex digits; empty on failure.
std::string finishHex(Sha256Digest& digest) {
  unsigned char bytes[Sha256Digest::kBytes];
  if (!digest.finish(bytes)) return std::string();
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (unsigned char b : bytes) out += std::string{kHex[b >> 4], kHex[b & 15]};
  return out;
}

}  // namespace

std::string sha256Hex(const void* data, size_t size) { return sha256Hex(data, size, {}); }

std::string sha256Hex(const void* data, size_t size, const std::vector<ByteSpan>& tail) {
  Sha256Digest digest;
  bool ok = digest.update(data, size);
  for (const ByteSpan& part : tail) ok = ok && digest.update(part.data, part.size);
  return ok ? finishHex(digest) : std::string();
}

std::string sha256Hex(const std::string& bytes) { return sha256Hex(bytes.data(), bytes.size()); }

Result<std::string> sha256File(const std::string& path) {
  os::InputFile file;
  if (!file.open(path)) return makeError(path + ": cannot open");
  Sha256Digest digest;
  if (!digest.ok()) return makeError(path + ": SHA-256 is not available");
  std::vector<char> chunk(1 << 20);
  for (;;) {
    const int64_t n = file.read(chunk.data(), chunk.size());
    if (n < 0) return makeError(path + ": read error");
    if (n == 0) break;
    if (!digest.update(chunk.data(), static_cast<size_t>(n)))
      return makeError(path + ": SHA-256 failed");
  }
  std::string hex = finishHex(digest);
  if (hex.empty()) return makeError(path + ": SHA-256 failed");
  return hex;
}

}  // namespace smpl
