// SHA-256 through OpenSSL's EVP digest API (Debian's libssl-dev): a well-kept
// implementation rather than our own. Files are hashed in 1 MiB chunks, so
// memory stays flat whatever the output size.
#include "core/io/sha256.h"

#include <openssl/evp.h>

#include <fstream>
#include <memory>
#include <vector>

namespace smpl {
namespace {

using DigestContext = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

std::string hex(const unsigned char* digest, unsigned int size) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) {
    out += kHex[digest[i] >> 4];
    out += kHex[digest[i] & 15];
  }
  return out;
}

DigestContext newSha256() {
  DigestContext ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (ctx && EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) ctx.reset();
  return ctx;
}

std::string finish(EVP_MD_CTX* ctx) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (EVP_DigestFinal_ex(ctx, digest, &size) != 1) return std::string();
  return hex(digest, size);
}

}  // namespace

std::string sha256Hex(const void* data, size_t size) { return sha256Hex(data, size, nullptr, 0); }

std::string sha256Hex(const void* data, size_t size, const void* tail, size_t tail_size) {
  DigestContext ctx = newSha256();
  if (!ctx || EVP_DigestUpdate(ctx.get(), data, size) != 1) return std::string();
  if (tail_size > 0 && EVP_DigestUpdate(ctx.get(), tail, tail_size) != 1) return std::string();
  return finish(ctx.get());
}

std::string sha256Hex(const std::string& bytes) { return sha256Hex(bytes.data(), bytes.size()); }

Result<std::string> sha256File(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return makeError(path + ": cannot open");
  DigestContext ctx = newSha256();
  if (!ctx) return makeError(path + ": SHA-256 is not available (OpenSSL)");
  std::vector<char> chunk(1 << 20);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    if (in.gcount() > 0 &&
        EVP_DigestUpdate(ctx.get(), chunk.data(), static_cast<size_t>(in.gcount())) != 1)
      return makeError(path + ": SHA-256 failed");
  }
  if (in.bad()) return makeError(path + ": read error");
  std::string digest = finish(ctx.get());
  if (digest.empty()) return makeError(path + ": SHA-256 failed");
  return digest;
}

}  // namespace smpl
