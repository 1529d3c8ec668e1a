// Escaping of untrusted text for one-line error messages.
#include "core/io/printable.h"

#include <algorithm>
#include <cstdint>

namespace smpl {
namespace {

// Length of the well-formed UTF-8 sequence starting at text[i] (RFC 3629:
// no overlong forms, no surrogates, nothing above U+10FFFF), or 0.
size_t utf8Length(std::string_view text, size_t i, uint32_t* cp) {
  const auto byte = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  const uint8_t b0 = byte(i);
  size_t n;
  uint32_t min;
  if (b0 < 0x80) return *cp = b0, 1;
  if ((b0 & 0xE0) == 0xC0)
    n = 2, min = 0x80, *cp = b0 & 0x1F;
  else if ((b0 & 0xF0) == 0xE0)
    n = 3, min = 0x800, *cp = b0 & 0x0F;
  else if ((b0 & 0xF8) == 0xF0)
    n = 4, min = 0x10000, *cp = b0 & 0x07;
  else
    return 0;
  if (i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    *cp = (*cp << 6) | (byte(i + k) & 0x3F);
  }
  if (*cp < min || *cp > 0x10FFFF || (*cp >= 0xD800 && *cp <= 0xDFFF)) return 0;
  return n;
}

bool isControl(uint32_t cp) { return cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F); }

void appendHex(std::string* out, uint8_t b) {
  static const char kDigits[] = "0123456789abcdef";
  *out += "\\x";
  *out += kDigits[b >> 4];
  *out += kDigits[b & 15];
}

}  // namespace

std::string printable(std::string_view text, size_t max_bytes) {
  std::string out;
  out.reserve(std::min(text.size(), max_bytes) + 8);
  for (size_t i = 0; i < text.size();) {
    if (out.size() >= max_bytes) return out + "...";
    uint32_t cp = 0;
    const size_t n = utf8Length(text, i, &cp);
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

}  // namespace smpl
