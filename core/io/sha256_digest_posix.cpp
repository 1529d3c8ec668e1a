// Sha256Digest on OpenSSL's EVP digest API (POSIX builds).
#include <openssl/evp.h>

#include <algorithm>

#include "core/io/sha256_digest.h"

namespace smpl {

struct Sha256Digest::State {
  EVP_MD_CTX* ctx = nullptr;
  ~State() { EVP_MD_CTX_free(ctx); }
};

Sha256Digest::Sha256Digest() : state_(new State) {
  state_->ctx = EVP_MD_CTX_new();
  if (!state_->ctx || EVP_DigestInit_ex(state_->ctx, EVP_sha256(), nullptr) != 1) state_.reset();
}

Sha256Digest::~Sha256Digest() = default;

bool Sha256Digest::update(const void* data, size_t size) {
  return state_ && (size == 0 || EVP_DigestUpdate(state_->ctx, data, size) == 1);
}

bool Sha256Digest::finish(unsigned char digest[kBytes]) {
  unsigned char out[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (!state_ || EVP_DigestFinal_ex(state_->ctx, out, &size) != 1 || size != kBytes) return false;
  std::copy(out, out + kBytes, digest);
  return true;
}

}  // namespace smpl
