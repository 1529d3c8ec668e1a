// One SHA-256 computation (FIPS 180-4) by the platform's well-kept
// implementation: OpenSSL's EVP API on POSIX builds (sha256_digest_posix.cpp,
// Debian's libssl-dev), Windows' CNG (bcrypt) on Windows builds
// (sha256_digest_win32.cpp), libmd on WebAssembly (sha256_digest_wasm.cpp).
// Used by sha256.cpp only.
#pragma once

#include <cstddef>
#include <memory>

namespace smpl {

class Sha256Digest {
 public:
  Sha256Digest();  // ok() is false when the implementation is not available
  ~Sha256Digest();
  Sha256Digest(const Sha256Digest&) = delete;
  Sha256Digest& operator=(const Sha256Digest&) = delete;

  bool ok() const { return state_ != nullptr; }
  bool update(const void* data, size_t size);  // false on failure
  static constexpr size_t kBytes = 32;
  // The digest; false on failure. Once per object.
  bool finish(unsigned char digest[kBytes]);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace smpl
