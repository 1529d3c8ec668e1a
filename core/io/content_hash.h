// A 64-bit content hash, to tell whether an input or a set of options changed
// since an output was made (batch up-to-date check, request/producer.h). Not
// cryptographic: it detects changes, it does not resist forgery. Stable across
// runs, machines and builds (fixed constants, little-endian word order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/result.h"

namespace smpl {

// Incremental hash: FNV-1a over 8-byte little-endian words with a
// multiply-xorshift finaliser (murmur3 fmix64) on output.
class ContentHash {
 public:
  void add(const void* data, size_t size);
  void add(const std::string& text);  // length first, so ("ab","c") != ("a","bc")
  uint64_t value() const;
  std::string hex() const;  // 16 lowercase hex digits

 private:
  uint64_t h_ = 1469598103934665603ull;
  uint64_t size_ = 0;     // bytes added
  uint64_t pending_ = 0;  // the incomplete last word
};

// Hash of a file's bytes, read in 1 MB chunks (memory stays bounded).
// Errors: "<path>: cannot open|read: <strerror>".
Result<uint64_t> hashFileContent(const std::string& path);

}  // namespace smpl
