// .usda text forms (usd_text.h).
#include "writers/usd/usd_text.h"

#include <charconv>
#include <cstdio>

namespace smpl {
namespace usd {
namespace {

template <typename T>
void appendShortest(std::string& out, T v) {
  if (v == 0) {  // both zeros as "0": the same bytes for -0 and +0
    out += '0';
    return;
  }
  char text[64];
  const std::to_chars_result r = std::to_chars(text, text + sizeof text, v);
  out.append(text, r.ptr);
}

}  // namespace

void appendFloat(std::string& out, float v) { appendShortest(out, v); }

void appendDouble(std::string& out, double v) { appendShortest(out, v); }

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
