#include "core/io/name_component.h"

#include <cstdint>

#include "core/io/sha256.h"

namespace smpl {
namespace {

constexpr size_t kHashDigits = 16;

bool keptAnywhere(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
         c == '_';
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;  // lower-case escapes are never made, so they are not read either
}

std::string escaped(std::string_view id) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(id.size());
  for (size_t i = 0; i < id.size(); ++i) {
    const auto c = static_cast<unsigned char>(id[i]);
    const bool dot_inside = c == '.' && i > 0 && i + 1 < id.size();
    if (keptAnywhere(c) || dot_inside) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

}  // namespace

std::string safeNameComponent(std::string_view id) {
  if (id.empty()) return "%";
  std::string name = escaped(id);
  if (name.size() <= kMaxNameComponent) return name;
  size_t keep = kMaxNameComponent - 1 - kHashDigits;
  // Never cut inside "%XX" ('%' only ever starts an escape): back to its '%'.
  if (name[keep - 1] == '%')
    keep -= 1;
  else if (name[keep - 2] == '%')
    keep -= 2;
  const std::string hash = sha256Hex(id.data(), id.size()).substr(0, kHashDigits);
  return name.substr(0, keep) + "~" + hash;
}

std::optional<std::string> idOfNameComponent(std::string_view component) {
  if (component == "%") return std::string();
  std::string id;
  for (size_t i = 0; i < component.size(); ++i) {
    if (component[i] != '%') {
      id += component[i];
      continue;
    }
    if (i + 2 >= component.size()) return std::nullopt;
    const int hi = hexValue(component[i + 1]), lo = hexValue(component[i + 2]);
    if (hi < 0 || lo < 0) return std::nullopt;
    id += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  if (safeNameComponent(id) != component) return std::nullopt;  // not a name this maps to
  return id;
}

}  // namespace smpl
