// Sha256Digest on libmd's SHA-2 (WebAssembly builds: Debian's libmd source,
// built by scripts/wasm-deps.sh; no OpenSSL there).
#include <sha2.h>

#include "core/io/sha256_digest.h"

namespace smpl {

struct Sha256Digest::State {
  SHA2_CTX ctx;
};

Sha256Digest::Sha256Digest() : state_(new State) { SHA256Init(&state_->ctx); }

Sha256Digest::~Sha256Digest() = default;

bool Sha256Digest::update(const void* data, size_t size) {
  if (!state_) return false;
  if (size > 0) SHA256Update(&state_->ctx, static_cast<const uint8_t*>(data), size);
  return true;
}

std::string Sha256Digest::finishHex() {
  if (!state_) return std::string();
  uint8_t digest[SHA256_DIGEST_LENGTH];
  SHA256Final(digest, &state_->ctx);
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (uint8_t b : digest) out += std::string{kHex[b >> 4], kHex[b & 15]};
  return out;
}

}  // namespace smpl
