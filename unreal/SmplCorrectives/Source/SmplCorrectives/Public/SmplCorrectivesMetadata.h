// SmplCorrectivesMetadata.h: the sidecar <file>.smpl.json -> smpl_correctives::Layout
// (header-only, C++17 standard library only).
//
// Why our own small JSON reader: the sidecar is untrusted input, and parsing is
// part of what can be wrong; with it here, CI tests it (tests/unit/unreal/
// runtime_metadata_test.cpp) and the Unreal glue only loads the file's text.
// The reader accepts RFC 8259 JSON, nests at most 64 levels, and reports the
// first problem with its byte offset. Keys the correctives do not need are
// skipped, never an error (docs/file-contract.md, "Metadata").
#pragma once

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "SmplCorrectivesCore.h"

namespace smpl_correctives {
namespace json {

/// A parsed JSON value (plain data; members keep file order).
struct Value {
  enum Kind { kNull, kBool, kNumber, kString, kArray, kObject } kind = kNull;
  bool boolean = false;
  double number = 0.0;
  std::string text;
  std::vector<Value> items;
  std::vector<std::pair<std::string, Value>> members;

  /// The member named `key` of an object (the last one if repeated), else null.
  const Value* find(const std::string& key) const {
    const Value* found = nullptr;
    for (const auto& m : members)
      if (m.first == key) found = &m.second;
    return found;
  }
};

class Parser {
 public:
  /// Keeps its own copy of the text (a temporary argument is safe).
  explicit Parser(std::string text)
      : text_(std::move(text)),
        p_(text_.data()),
        begin_(text_.data()),
        end_(text_.data() + text_.size()) {}
  Parser(const Parser&) = delete;  // p_ points into text_
  Parser& operator=(const Parser&) = delete;

  /// Parses the whole text; false and error() on the first problem.
  bool parse(Value* out) {
    skipSpace();
    if (!value(out, 0)) return false;
    skipSpace();
    return p_ == end_ || fail("unexpected text after the JSON value");
  }
  const std::string& error() const { return error_; }

 private:
  static constexpr int kMaxDepth = 64;

  bool fail(const char* what) {
    if (error_.empty()) error_ = std::string(what) + " at byte " + std::to_string(p_ - begin_);
    return false;
  }
  void skipSpace() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
  }
  bool literal(const char* word) {
    size_t n = std::char_traits<char>::length(word);
    if (size_t(end_ - p_) < n || std::string(p_, n) != word) return fail("invalid literal");
    p_ += n;
    return true;
  }

  bool value(Value* out, int depth) {
    if (depth > kMaxDepth) return fail("nesting deeper than 64 levels");
    if (p_ == end_) return fail("unexpected end of text");
    switch (*p_) {
      case '{':
        return object(out, depth);
      case '[':
        return array(out, depth);
      case '"':
        out->kind = Value::kString;
        return string(&out->text);
      case 't':
        out->kind = Value::kBool;
        out->boolean = true;
        return literal("true");
      case 'f':
        out->kind = Value::kBool;
        out->boolean = false;
        return literal("false");
      case 'n':
        out->kind = Value::kNull;
        return literal("null");
      default:
        out->kind = Value::kNumber;
        return number(&out->number);
    }
  }

  bool object(Value* out, int depth) {
    out->kind = Value::kObject;
    ++p_;
    skipSpace();
    if (p_ < end_ && *p_ == '}') return ++p_, true;
    while (true) {
      std::pair<std::string, Value> member;
      skipSpace();
      if (p_ == end_ || *p_ != '"') return fail("expected a member name");
      if (!string(&member.first)) return false;
      skipSpace();
      if (p_ == end_ || *p_ != ':') return fail("expected ':'");
      ++p_;
      skipSpace();
      if (!value(&member.second, depth + 1)) return false;
      out->members.push_back(std::move(member));
      skipSpace();
      if (p_ < end_ && *p_ == ',') {
        ++p_;
        continue;
      }
      if (p_ < end_ && *p_ == '}') return ++p_, true;
      return fail("expected ',' or '}'");
    }
  }

  bool array(Value* out, int depth) {
    out->kind = Value::kArray;
    ++p_;
    skipSpace();
    if (p_ < end_ && *p_ == ']') return ++p_, true;
    while (true) {
      out->items.emplace_back();
      skipSpace();
      if (!value(&out->items.back(), depth + 1)) return false;
      skipSpace();
      if (p_ < end_ && *p_ == ',') {
        ++p_;
        continue;
      }
      if (p_ < end_ && *p_ == ']') return ++p_, true;
      return fail("expected ',' or ']'");
    }
  }

  bool number(double* out) {
    const char* start = p_;
    if (p_ < end_ && *p_ == '-') ++p_;
    if (p_ == end_ || !isDigit(*p_)) return fail("invalid value");
    if (*p_ == '0')
      ++p_;
    else
      while (p_ < end_ && isDigit(*p_)) ++p_;
    if (p_ < end_ && *p_ == '.') {
      ++p_;
      if (p_ == end_ || !isDigit(*p_)) return fail("invalid number");
      while (p_ < end_ && isDigit(*p_)) ++p_;
    }
    if (p_ < end_ && (*p_ == 'e' || *p_ == 'E')) {
      ++p_;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !isDigit(*p_)) return fail("invalid number");
      while (p_ < end_ && isDigit(*p_)) ++p_;
    }
    std::string token(start, p_);  // strtod needs a terminated copy (the text may not be)
    *out = std::strtod(token.c_str(), nullptr);
    return std::isfinite(*out) || fail("number out of range");
  }
  static bool isDigit(char c) { return c >= '0' && c <= '9'; }

  bool hex4(unsigned* out) {
    if (end_ - p_ < 4) return fail("truncated \\u escape");
    *out = 0;
    for (int i = 0; i < 4; ++i, ++p_) {
      char c = *p_;
      unsigned d = c >= '0' && c <= '9'   ? unsigned(c - '0')
                   : c >= 'a' && c <= 'f' ? unsigned(c - 'a' + 10)
                   : c >= 'A' && c <= 'F' ? unsigned(c - 'A' + 10)
                                          : 16u;
      if (d == 16u) return fail("invalid \\u escape");
      *out = *out * 16 + d;
    }
    return true;
  }

  static void appendUtf8(unsigned cp, std::string* out) {
    if (cp < 0x80) {
      out->push_back(char(cp));
      return;
    }
    if (cp < 0x800) {
      out->push_back(char(0xC0 | (cp >> 6)));
    } else if (cp < 0x10000) {
      out->push_back(char(0xE0 | (cp >> 12)));
      out->push_back(char(0x80 | ((cp >> 6) & 0x3F)));
    } else {
      out->push_back(char(0xF0 | (cp >> 18)));
      out->push_back(char(0x80 | ((cp >> 12) & 0x3F)));
      out->push_back(char(0x80 | ((cp >> 6) & 0x3F)));
    }
    out->push_back(char(0x80 | (cp & 0x3F)));
  }

  bool escape(std::string* out) {
    if (p_ == end_) return fail("unterminated string");
    char c = *p_++;
    switch (c) {
      case '"':
      case '\\':
      case '/':
        out->push_back(c);
        return true;
      case 'b':
        out->push_back('\b');
        return true;
      case 'f':
        out->push_back('\f');
        return true;
      case 'n':
        out->push_back('\n');
        return true;
      case 'r':
        out->push_back('\r');
        return true;
      case 't':
        out->push_back('\t');
        return true;
      case 'u':
        break;
      default:
        return fail("invalid escape");
    }
    unsigned cp = 0;
    if (!hex4(&cp)) return false;
    if (cp >= 0xD800 && cp < 0xDC00) {  // a surrogate pair
      unsigned low = 0;
      if (end_ - p_ < 2 || p_[0] != '\\' || p_[1] != 'u') return fail("unpaired surrogate");
      p_ += 2;
      if (!hex4(&low)) return false;
      if (low < 0xDC00 || low > 0xDFFF) return fail("unpaired surrogate");
      cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    } else if (cp >= 0xDC00 && cp < 0xE000) {
      return fail("unpaired surrogate");
    }
    appendUtf8(cp, out);
    return true;
  }

  bool string(std::string* out) {
    ++p_;  // the opening quote
    while (true) {
      if (p_ == end_) return fail("unterminated string");
      char c = *p_++;
      if (c == '"') return true;
      if (static_cast<unsigned char>(c) < 0x20) return fail("control character in a string");
      if (c == '\\') {
        if (!escape(out)) return false;
      } else {
        out->push_back(c);
      }
    }
  }

  std::string text_;
  const char* p_;
  const char* begin_;
  const char* end_;
  std::string error_;
};

}  // namespace json

namespace detail {

inline bool readInt(const json::Value& v, int* out) {
  if (v.kind != json::Value::kNumber || v.number != std::floor(v.number) ||
      std::fabs(v.number) > 1e9)
    return false;
  *out = int(v.number);
  return true;
}

inline std::string readNumbers(const json::Value& parent, const char* key, const std::string& where,
                               std::vector<double>* out) {
  const json::Value* v = parent.find(key);
  if (!v || v->kind != json::Value::kArray)
    return where + "." + key + " must be an array of numbers";
  for (const json::Value& item : v->items) {
    if (item.kind != json::Value::kNumber)
      return where + "." + key + " must be an array of numbers";
    out->push_back(item.number);
  }
  return "";
}

inline std::string readCorrective(const json::Value& e, const std::string& where, Corrective* c) {
  if (e.kind != json::Value::kObject) return where + " must be an object";
  const json::Value* target = e.find("target");
  const json::Value* feature = e.find("feature");
  if (!target || target->kind != json::Value::kString) return where + ".target must be a string";
  if (!feature || !readInt(*feature, &c->feature)) return where + ".feature must be an integer";
  c->target = target->text;
  for (auto field : {std::make_pair("scale", &c->scale), std::make_pair("offset", &c->offset)}) {
    const json::Value* v = e.find(field.first);
    if (v && v->kind != json::Value::kNumber)
      return where + "." + field.first + " must be a number";
    if (v) *field.second = v->number;
  }
  const json::Value* rectified = e.find("rectified");
  c->rectified = rectified && rectified->kind == json::Value::kBool && rectified->boolean;
  return "";
}

inline std::string readBasis(const json::Value& b, Basis* out) {
  const std::string where = "metadata: 'corrective_basis'";
  if (b.kind != json::Value::kObject) return where + " must be an object";
  const json::Value* targets = b.find("targets");
  if (!targets || targets->kind != json::Value::kArray)
    return where + ".targets must be an array of strings";
  for (const json::Value& t : targets->items) {
    if (t.kind != json::Value::kString) return where + ".targets must be an array of strings";
    out->targets.push_back(t.text);
  }
  std::string error = readNumbers(b, "matrix", where, &out->matrix);
  if (error.empty()) error = readNumbers(b, "scale", where, &out->scale);
  if (error.empty()) error = readNumbers(b, "offset", where, &out->offset);
  return error;
}

}  // namespace detail

/// Layout from the sidecar's text (docs/file-contract.md, "Metadata"):
/// joint_names, parents, up_axis (default "+Y"), correctives (feature, target,
/// scale = 1, offset = 0, rectified = false) and corrective_basis when present.
/// Returns an error line ("metadata: ...") or empty; the layout is validated.
inline std::string parseLayout(const std::string& text, Layout* out) {
  json::Value root;
  json::Parser parser(text);
  if (!parser.parse(&root)) return "metadata: invalid JSON: " + parser.error();
  if (root.kind != json::Value::kObject) return "metadata: expected a JSON object";
  Layout layout;
  const json::Value* names = root.find("joint_names");
  const json::Value* parents = root.find("parents");
  if (!names || names->kind != json::Value::kArray || !parents ||
      parents->kind != json::Value::kArray)
    return "metadata: 'joint_names' and 'parents' must be arrays";
  for (const json::Value& n : names->items) {
    if (n.kind != json::Value::kString) return "metadata: 'joint_names' must hold strings";
    layout.joint_names.push_back(n.text);
  }
  for (const json::Value& p : parents->items) {
    int parent = 0;
    if (!detail::readInt(p, &parent)) return "metadata: 'parents' must hold integers";
    layout.parents.push_back(parent);
  }
  const json::Value* bones = root.find("bone_names");  // --skeleton-names
  if (bones && bones->kind != json::Value::kArray) return "metadata: 'bone_names' must be an array";
  for (size_t i = 0; bones && i < bones->items.size(); ++i) {
    if (bones->items[i].kind != json::Value::kString)
      return "metadata: 'bone_names' must hold strings";
    layout.bone_names.push_back(bones->items[i].text);
  }
  const json::Value* up = root.find("up_axis");
  if (up && up->kind == json::Value::kString) layout.up_axis = up->text;
  const json::Value* correctives = root.find("correctives");
  if (correctives && correctives->kind != json::Value::kArray)
    return "metadata: 'correctives' must be an array";
  for (size_t i = 0; correctives && i < correctives->items.size(); ++i) {
    Corrective c;
    std::string error = detail::readCorrective(
        correctives->items[i], "metadata: 'correctives'[" + std::to_string(i) + "]", &c);
    if (!error.empty()) return error;
    layout.correctives.push_back(c);
  }
  const json::Value* basis = root.find("corrective_basis");
  if (basis) {
    std::string error = detail::readBasis(*basis, &layout.basis);
    if (!error.empty()) return error;
  }
  std::string error = validate(layout);
  if (error.empty()) *out = std::move(layout);
  return error;
}

}  // namespace smpl_correctives
