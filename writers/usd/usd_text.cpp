// .usda text forms (usd_text.h).
#include "writers/usd/usd_text.h"

#include <cstdio>
#include <cstdlib>

namespace smpl {
namespace usd {
namespace {

// The fewest significant digits (from `least`: 6, which %g shortens by its
// trailing zeros; up to 9 for a float, 17 for
// a double: always exact) whose %g text reads back as `v`. snprintf and
// strtod, not std::to_chars: emscripten's libc++ has no floating-point
// to_chars, and every C library the builds use (glibc, musl, mingw-w64's
// own printf) converts exactly, so the text is the same everywhere.
template <typename T>
void appendShortest(std::string& out, T v, int least, int most) {
  if (v == 0) {  // both zeros as "0": the same bytes for -0 and +0
    out += '0';
    return;
  }
  char text[40];
  for (int digits = least; digits <= most; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, double(v));
    if (static_cast<T>(std::strtod(text, nullptr)) == v) break;
  }
  out += text;
}

}  // namespace

void appendFloat(std::string& out, float v) { appendShortest(out, v, 6, 9); }

void appendDouble(std::string& out, double v) { appendShortest(out, v, 6, 17); }

void appendFloat3(std::string& out, float x, float y, float z) {
  out += '(';
  appendFloat(out, x);
  out += ", ";
  appendFloat(out, y);
  out += ", ";
  appendFloat(out, z);
  out += ')';
}

void appendQuat(std::string& out, const Eigen::Quaternionf& q) {
  out += '(';
  appendFloat(out, q.w());
  out += ", ";
  appendFloat(out, q.x());
  out += ", ";
  appendFloat(out, q.y());
  out += ", ";
  appendFloat(out, q.z());
  out += ')';
}

void appendTranslationMatrix(std::string& out, const Eigen::Vector3d& t) {
  out += "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (";
  appendDouble(out, t.x());
  out += ", ";
  appendDouble(out, t.y());
  out += ", ";
  appendDouble(out, t.z());
  out += ", 1))";
}

bool isIdentifier(const std::string& name) {
  if (name.empty()) return false;
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
    const bool digit = c >= '0' && c <= '9';
    if (!letter && !(digit && i > 0)) return false;
  }
  return true;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace usd
}  // namespace smpl
