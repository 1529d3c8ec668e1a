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

bool Sha256Digest::finish(unsigned char digest[kBytes]) {
  if (!state_) return false;
  SHA256Final(digest, &state_->ctx);
  return true;
}

}  // namespace smpl
