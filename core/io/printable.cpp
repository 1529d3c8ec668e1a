// Escaping of untrusted text for one-line error messages.
#include "core/io/printable.h"

#include <algorithm>
#include <cstdint>

#include "core/utf8.h"

namespace smpl {
namespace {

bool isControl(uint32_t cp) { return cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F); }

void appendHex(std::string* out, uint8_t b) {
  static const char kDigits[] = "0123456789abcdef";
  *out += "\\x";
  *out += kDigits[b >> 4];
  *out += kDigits[b & 15];
}

// Moves a cut position of escaped text `s` off the inside of a UTF-8 sequence
// or a "\xNN" escape: backwards (head) or forwards (tail).
size_t cutBoundary(const std::string& s, size_t at, bool backwards) {
  for (size_t k = 1; k <= 3 && k <= at; ++k)
    if (s[at - k] == '\\' && at - k + 1 < s.size() && s[at - k + 1] == 'x' && at - k + 4 > at)
      return backwards ? at - k : std::min(s.size(), at - k + 4);
  while (at > 0 && at < s.size() && (static_cast<uint8_t>(s[at]) & 0xC0) == 0x80)
    backwards ? --at : ++at;
  return at;
}

}  // namespace

std::string printable(std::string_view text, size_t max_bytes) {
  std::string out;
  out.reserve(std::min(text.size(), max_bytes) + 8);
  for (size_t i = 0; i < text.size();) {
    if (out.size() >= max_bytes) return out + "...";
    uint32_t cp = 0;
    const size_t n = utf8SequenceLength(text, i, &cp);
    if (n == 0 || isControl(cp)) {
      for (size_t k = 0; k < (n == 0 ? 1 : n); ++k)
        appendHex(&out, static_cast<uint8_t>(text[i + k]));
      i += n == 0 ? 1 : n;
      continue;
    }
    out.append(text.substr(i, n));
    i += n;
  }
  return out;
}

std::string printableMiddle(std::string_view text, size_t max_bytes) {
  const std::string all = printable(text, static_cast<size_t>(-1));
  if (all.size() <= max_bytes) return all;
  const std::string dots = "...";
  const size_t room = max_bytes > dots.size() ? max_bytes - dots.size() : 0;
  const size_t head = cutBoundary(all, room / 2, true);
  const size_t tail = cutBoundary(all, all.size() - (room - room / 2), false);
  return all.substr(0, head) + dots + all.substr(tail);
}

}  // namespace smpl
