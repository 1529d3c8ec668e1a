// A minimal deterministic JSON writer for the conformance kit
// (tools/reference/conformance_kit.cpp): numbers as %.17g (round-trip
// doubles), strings escaped per RFC 8259. Not a general serializer.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace smpl {

/// Builds one JSON text; commas are placed by the writer.
class KitJson {
 public:
  KitJson& beginObject() { return open('{'); }
  KitJson& beginArray() { return open('['); }
  /// Closes the innermost object or array.
  KitJson& end() {
    out_ += closers_.back();
    closers_.pop_back();
    first_.pop_back();
    return *this;
  }
  KitJson& key(const std::string& k) {
    string(k);
    out_ += ':';
    after_key_ = true;
    return *this;
  }
  KitJson& string(const std::string& s) {
    separate();
    out_ += '"';
    for (unsigned char c : s) {
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += char(c);
      } else if (c < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else {
        out_ += char(c);
      }
    }
    out_ += '"';
    return *this;
  }
  KitJson& number(double v) {
    separate();
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v == 0 ? 0.0 : v);  // never "-0"
    out_ += buf;
    return *this;
  }
  KitJson& boolean(bool v) {
    separate();
    out_ += v ? "true" : "false";
    return *this;
  }
  KitJson& numbers(const std::vector<double>& v) {
    beginArray();
    for (double x : v) number(x);
    return end();
  }
  /// The text, with a final newline.
  std::string text() const { return out_ + "\n"; }

 private:
  KitJson& open(char c) {
    separate();
    out_ += c;
    closers_ += c == '{' ? '}' : ']';
    first_.push_back(true);
    return *this;
  }
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_.empty()) {
      if (!first_.back()) out_ += ',';
      first_.back() = false;
    }
  }
  std::string out_, closers_;
  std::vector<bool> first_;
  bool after_key_ = false;
};

}  // namespace smpl
