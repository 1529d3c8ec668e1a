// Sha256Digest on Windows' CNG (bcrypt) hash API (Windows builds).
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
// windows.h first: bcrypt.h needs its types.
#include <bcrypt.h>

#include "core/io/sha256_digest.h"

namespace smpl {

struct Sha256Digest::State {
  BCRYPT_ALG_HANDLE alg = nullptr;
  BCRYPT_HASH_HANDLE hash = nullptr;
  ~State() {
    if (hash) BCryptDestroyHash(hash);
    if (alg) BCryptCloseAlgorithmProvider(alg, 0);
  }
};

Sha256Digest::Sha256Digest() : state_(new State) {
  if (BCryptOpenAlgorithmProvider(&state_->alg, BCRYPT_SHA256_ALGORITHM, nullptr, 0) != 0 ||
      BCryptCreateHash(state_->alg, &state_->hash, nullptr, 0, nullptr, 0, 0) != 0)
    state_.reset();
}

Sha256Digest::~Sha256Digest() = default;

bool Sha256Digest::update(const void* data, size_t size) {
  if (!state_) return false;
  const auto* p = static_cast<const UCHAR*>(data);
  while (size > 0) {  // ULONG lengths: at most 1 GiB per call
    const ULONG n = static_cast<ULONG>(size < (1u << 30) ? size : (1u << 30));
    if (BCryptHashData(state_->hash, const_cast<PUCHAR>(p), n, 0) != 0) return false;
    p += n;
    size -= n;
  }
  return true;
}

bool Sha256Digest::finish(unsigned char digest[kBytes]) {
  return state_ && BCryptFinishHash(state_->hash, digest, kBytes, 0) == 0;
}

}  // namespace smpl
