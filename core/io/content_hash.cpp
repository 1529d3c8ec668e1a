// FNV-1a (Fowler, Noll, Vo) on 64-bit words; fmix64 from MurmurHash3 (Appleby)
// spreads the final state. Bytes are folded in word by word in little-endian
// order regardless of how the input is split into add() calls.
#include "core/io/content_hash.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include "core/os/files.h"

namespace smpl {
namespace {

constexpr uint64_t kPrime = 1099511628211ull;

uint64_t fmix64(uint64_t k) {
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdull;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ull;
  return k ^ (k >> 33);
}

}  // namespace

void ContentHash::add(const void* data, size_t size) {
  const auto* p = static_cast<const uint8_t*>(data);
  size_t i = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  if (size_ % 8 == 0) {  // aligned to the word stream: whole words at once
    for (; i + 8 <= size; i += 8) {
      uint64_t w;
      std::memcpy(&w, p + i, 8);
      h_ = (h_ ^ w) * kPrime;
    }
    size_ += i;
  }
#endif
  for (; i < size; ++i) {
    // Byte i of the stream goes into bit 8*(n%8) of word n/8.
    const unsigned shift = static_cast<unsigned>(size_ % 8) * 8;
    pending_ |= static_cast<uint64_t>(p[i]) << shift;
    if (++size_ % 8 == 0) {
      h_ = (h_ ^ pending_) * kPrime;
      pending_ = 0;
    }
  }
}

void ContentHash::add(const std::string& text) {
  const uint64_t n = text.size();
  uint8_t le[8];
  for (int i = 0; i < 8; ++i) le[i] = static_cast<uint8_t>(n >> (8 * i));
  add(le, 8);
  add(text.data(), text.size());
}

uint64_t ContentHash::value() const { return fmix64((h_ ^ pending_) * kPrime ^ size_); }

std::string ContentHash::hex() const {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(value()));
  return buf;
}

Result<uint64_t> hashFileContent(const std::string& path) {
  os::InputFile file;
  if (!file.open(path)) return makeError(path + ": cannot open: " + os::errorText());
  std::vector<uint8_t> chunk(1 << 20);
  ContentHash h;
  for (;;) {
    const int64_t n = file.read(chunk.data(), chunk.size());
    if (n < 0) return makeError(path + ": cannot read: " + os::errorText());
    if (n == 0) break;
    h.add(chunk.data(), static_cast<size_t>(n));
  }
  return h.value();
}

}  // namespace smpl
