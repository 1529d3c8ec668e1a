// Whole zlib (RFC 1950) and gzip (RFC 1952) streams, as joblib writes its
// compressed files (compress=3, '.z', '.gz': joblib/compressor.py's
// BinaryZlibFile and BinaryGzipFile, one stream over the whole pickle).
// Unlike a zip member, such a stream declares no size, so the output grows in
// steps and each step is charged to the memory budget before it is
// allocated: a bomb ends with the budget error ("x.pkl: inflating the zlib
// stream would need 8.0 GiB; the limit is ...") instead of an allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/memory_budget.h"
#include "core/result.h"

namespace smpl {

// A byte buffer that grows in place: realloc, which for large blocks moves
// pages (glibc: mremap) instead of copying them, so doubling a 512 MiB buffer
// never holds 1.5 GiB, and new bytes are not zero-filled before zlib writes them.
class GrowableBytes {
 public:
  GrowableBytes() = default;
  GrowableBytes(GrowableBytes&& other) noexcept;
  GrowableBytes& operator=(GrowableBytes&& other) noexcept;
  GrowableBytes(const GrowableBytes&) = delete;
  GrowableBytes& operator=(const GrowableBytes&) = delete;
  ~GrowableBytes();

  uint8_t* data() { return bytes_; }
  const uint8_t* data() const { return bytes_; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // Sets the size; growing keeps the bytes (the new ones are unset). False
  // (nothing changed) when the allocation fails.
  bool resize(size_t size);
  std::vector<uint8_t> toVector() const { return std::vector<uint8_t>(bytes_, bytes_ + size_); }

 private:
  uint8_t* bytes_ = nullptr;
  size_t size_ = 0;
};

struct InflatedBytes {
  GrowableBytes data;
  MemoryCharge charge;   // `data`'s capacity held against the memory budget
  bool complete = true;  // false: stopped at max_bytes before the stream's end
};

enum class StreamFormat { Zlib, Gzip };

// Inflates the one stream at the start of `data` (bytes after its end are
// ignored, as joblib ignores them). Errors name `context`: corrupt or
// truncated data, more than `max_bytes` of output, the memory budget.
// With `stop_at_max`, reaching `max_bytes` is not an error: the first
// max_bytes inflated bytes are returned with complete = false, and nothing
// past them is inflated (the caller decides whether the prefix suffices).
Result<InflatedBytes> inflateStream(const uint8_t* data, size_t size, StreamFormat format,
                                    const std::string& context, uint64_t max_bytes = 16ull << 30,
                                    bool stop_at_max = false);

}  // namespace smpl
