// inflateStream: zlib's streaming inflate into a buffer that doubles as it
// fills, in place (GrowableBytes: realloc). Before each doubling the new size
// is charged while the old one still is (realloc may copy a small block),
// then the old charge is released.
#include "core/io/inflate.h"

#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace smpl {

GrowableBytes::GrowableBytes(GrowableBytes&& other) noexcept
    : bytes_(std::exchange(other.bytes_, nullptr)), size_(std::exchange(other.size_, 0)) {}

GrowableBytes& GrowableBytes::operator=(GrowableBytes&& other) noexcept {
  if (this != &other) {
    std::free(bytes_);
    bytes_ = std::exchange(other.bytes_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

GrowableBytes::~GrowableBytes() { std::free(bytes_); }

bool GrowableBytes::resize(size_t size) {
  if (size == 0) {
    std::free(bytes_);
    bytes_ = nullptr, size_ = 0;
    return true;
  }
  void* grown = std::realloc(bytes_, size);
  if (!grown) return false;
  bytes_ = static_cast<uint8_t*>(grown), size_ = size;
  return true;
}

namespace {

constexpr uint64_t kChunk = 1u << 30;  // z_stream counts are 32-bit

// Doubles `out` (at least 64 KiB, at most max_bytes), charging first.
Status grow(InflatedBytes* out, uint64_t max_bytes, const char* name, const std::string& context) {
  const uint64_t cap = out->data.size();
  if (cap >= max_bytes)
    return makeError(context + ": the " + name + " stream inflates to more than " +
                     formatBytes(max_bytes));
  const uint64_t next = std::min(max_bytes, std::max<uint64_t>(cap * 2, 64 << 10));
  MemoryCharge charge;
  if (Status st = charge.add(next, context, std::string("inflating the ") + name + " stream"); !st)
    return st;
  if (!out->data.resize(static_cast<size_t>(next)))
    return makeError(context + ": out of memory inflating the " + name + " stream to " +
                     formatBytes(next));
  out->charge = std::move(charge);
  return Status();
}

}  // namespace

Result<InflatedBytes> inflateStream(const uint8_t* data, size_t size, StreamFormat format,
                                    const std::string& context, uint64_t max_bytes,
                                    bool stop_at_max) {
  const char* name = format == StreamFormat::Gzip ? "gzip" : "zlib";
  InflatedBytes out;
  z_stream zs{};
  if (inflateInit2(&zs, format == StreamFormat::Gzip ? 31 : 15) != Z_OK)
    return makeError(context + ": cannot initialise zlib");
  uint64_t in_pos = 0, out_pos = 0;
  Status st;
  for (bool done = false; st && !done;) {
    if (zs.avail_in == 0 && in_pos < size) {
      zs.next_in = const_cast<Bytef*>(data + in_pos);  // zlib's API is not const-correct
      zs.avail_in = static_cast<uInt>(std::min<uint64_t>(size - in_pos, kChunk));
      in_pos += zs.avail_in;
    }
    if (out_pos == out.data.size() && stop_at_max && out_pos >= max_bytes) {
      // Full: complete only if the stream ends here (no byte more to write).
      uint8_t spare = 0;
      zs.next_out = &spare;
      zs.avail_out = 1;
      out.complete = inflate(&zs, Z_NO_FLUSH) == Z_STREAM_END && zs.avail_out == 1;
      break;
    }
    if (out_pos == out.data.size() && !(st = grow(&out, max_bytes, name, context))) break;
    zs.next_out = out.data.data() + out_pos;
    zs.avail_out = static_cast<uInt>(std::min<uint64_t>(out.data.size() - out_pos, kChunk));
    const uInt room = zs.avail_out, in_before = zs.avail_in;
    const int ret = inflate(&zs, Z_NO_FLUSH);
    out_pos += room - zs.avail_out;
    done = ret == Z_STREAM_END;
    if (ret == Z_NEED_DICT || ret == Z_DATA_ERROR || ret == Z_MEM_ERROR || ret == Z_STREAM_ERROR)
      st = makeError(context + ": corrupt " + name + " data (" +
                     (zs.msg ? zs.msg : "zlib error " + std::to_string(ret)) + ")");
    else if (!done && zs.avail_in == 0 && in_pos == size && zs.avail_out > 0)
      st = makeError(context + ": truncated " + name + " data (the stream ends after " +
                     std::to_string(size) + " bytes without its end marker)");
    else if (!done && room == zs.avail_out && in_before == zs.avail_in && zs.avail_out > 0)
      st = makeError(context + ": corrupt " + name + " data (no progress)");
  }
  inflateEnd(&zs);
  if (!st) return st.error();
  // Shrinking in place hands the unused tail back; the charge stays at the
  // capacity reached (the peak), which is what the budget saw.
  if (out_pos < out.data.size()) out.data.resize(static_cast<size_t>(out_pos));
  return out;
}

}  // namespace smpl
