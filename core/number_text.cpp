// The command line's number grammar (see the header); the value itself is
// converted by strtod/strtoll only after the text has matched the grammar, so
// their extensions (hex, inf, blanks, locale) never apply.
#include "core/number_text.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace smpl {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

size_t digits(std::string_view text, size_t at) {
  size_t n = 0;
  while (at + n < text.size() && isDigit(text[at + n])) ++n;
  return n;
}

std::string quoted(std::string_view text) {
  std::string q = "'";
  for (char c : text.substr(0, 64)) q += (c >= 0x20 && c < 0x7f) ? c : '?';  // a usage line
  return q + (text.size() > 64 ? "...'" : "'");
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

}  // namespace

size_t decimalPrefixLength(std::string_view text) {
  size_t at = text.size() > 0 && text[0] == '-' ? 1 : 0;
  const size_t whole = digits(text, at);
  at += whole;
  size_t fraction = 0;
  if (at < text.size() && text[at] == '.') {
    fraction = digits(text, at + 1);
    if (whole == 0 && fraction == 0) return 0;
    at += 1 + fraction;
  } else if (whole == 0) {
    return 0;
  }
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    size_t e = at + 1;
    if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
    const size_t exponent = digits(text, e);
    if (exponent > 0) at = e + exponent;
  }
  return at;
}

Result<double> parseDecimal(std::string_view text, double lo, double hi) {
  if (text.empty() || decimalPrefixLength(text) != text.size())
    return makeError(quoted(text) + " is not a decimal number");
  const std::string copy(text);
  errno = 0;
  const double v = std::strtod(copy.c_str(), nullptr);
  if (errno == ERANGE && std::abs(v) > 1) return makeError(quoted(text) + " is not finite");
  if (!(v >= lo && v <= hi))
    return makeError(quoted(text) + " is not in [" + number(lo) + ", " + number(hi) + "]");
  return v;
}

Result<int64_t> parseInteger(std::string_view text, int64_t lo, int64_t hi) {
  const size_t sign = !text.empty() && text[0] == '-' ? 1 : 0;
  if (text.size() == sign || digits(text, sign) != text.size() - sign)
    return makeError(quoted(text) + " is not an integer");
  const std::string copy(text);
  errno = 0;
  const long long v = std::strtoll(copy.c_str(), nullptr, 10);
  if (errno == ERANGE || v < lo || v > hi)
    return makeError(quoted(text) + " is not in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return static_cast<int64_t>(v);
}

}  // namespace smpl
