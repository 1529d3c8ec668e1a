#include "core/io/base64.h"

#include <cstdio>
#include <string>

#include "core/memory_budget.h"

namespace smpl {
namespace {

// The 6-bit value of a base64 character, or -1.
int sextet(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

size_t padding(std::string_view text) {
  size_t n = 0;
  while (n < 2 && n < text.size() && text[text.size() - 1 - n] == '=') ++n;
  return n;
}

}  // namespace

uint64_t base64DecodedSize(std::string_view text) {
  if (text.size() % 4 != 0) return text.size() / 4 * 3;
  return text.size() / 4 * 3 - padding(text);
}

Result<std::vector<uint8_t>> decodeBase64(std::string_view text, const std::string& context) {
  if (text.size() % 4 != 0)
    return makeError(context + ": base64 data is truncated (" + std::to_string(text.size()) +
                     " characters, not a multiple of 4)");
  const size_t pad = padding(text);
  const uint64_t size = base64DecodedSize(text);
  if (Status st = checkMemory(size, context, "the decoded base64 data"); !st) return st.error();
  std::vector<uint8_t> out;
  out.reserve(size);
  uint32_t group = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const bool padded = c == '=' && i >= text.size() - pad;
    const int v = padded ? 0 : sextet(c);
    if (v < 0) {
      char where[64];
      std::snprintf(where, sizeof where, "character 0x%02x at %zu", c, i);
      return makeError(context + ": not base64 (" + where + ")");
    }
    group = (group << 6) | static_cast<uint32_t>(v);
    if (i % 4 == 3) {
      for (int k = 2; k >= 0; --k) out.push_back(static_cast<uint8_t>(group >> (8 * k)));
      group = 0;
    }
  }
  out.resize(size);
  return out;
}

}  // namespace smpl
