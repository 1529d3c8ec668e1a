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

struct InflatedBytes {
  std::vector<uint8_t> data;
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
