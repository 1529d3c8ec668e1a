// The pickle virtual machine: reads opcodes of protocols 0-5 and builds the
// object graph in a Heap. Globals are resolved against the allow-list in
// pickle_objects.cpp; nothing named in the data is ever imported or called.
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

#include "core/io/pickle/pickle_internal.h"
#include "core/utf8.h"

namespace smpl {
namespace pickle {

namespace {

// Bytes payloads at least this long are viewed in place, not copied.
constexpr uint64_t kViewBytes = 4096;

class Vm {
 public:
  Vm(Heap& heap, const uint8_t* data, size_t size, size_t start, const PickleLimits& limits)
      : heap_(heap), data_(data), size_(size), pos_(start), limits_(limits) {}
  Result<Ref> run();
  size_t position() const { return pos_; }

 private:
  Status step(uint8_t op);
  Status stepText(uint8_t op, bool* handled);
  Status stepBinary(uint8_t op, bool* handled);
  Status stepPayload(uint8_t op, bool* handled);
  Status stepContainers(uint8_t op, bool* handled);
  Status stepMemo(uint8_t op, bool* handled);
  Status stepObjects(uint8_t op, bool* handled);

  // Input
  Status need(uint64_t n);
  Result<uint64_t> readUint(int bytes);
  Result<std::string> readLine();
  Status checkPayload(uint64_t n, const char* what);
  std::string take(size_t n);
  // Stack
  Status push(Ref r);
  Result<Ref> pop();
  Result<Ref> top();
  Result<std::vector<Ref>> popMark();
  Result<Ref> make(PyObj obj) { return heap_.add(std::move(obj)); }
  Result<Ref> makeTuple(std::vector<Ref> items) {
    PK_TRY(heap_.charge(items.size() * sizeof(Ref), "tuple"));
    PyObj o;
    o.kind = Kind::Tuple;
    o.items = std::move(items);
    return make(std::move(o));
  }
  Status pushNew(PyObj obj);
  Status pushInt(int64_t v, Kind kind = Kind::Int);
  Status pushFloat(double v, std::string exact = {});
  Status pushString(std::string s, Kind kind);
  Status pushContainer(Kind kind, std::vector<Ref> items);
  // Memo
  Status memoPut(uint64_t index);
  Status memoGet(uint64_t index);
  // Opcode bodies
  Status textInt(const std::string& line, bool is_long);
  Status textFloat(const std::string& line);
  Status textString(const std::string& line);
  Status textUnicode(const std::string& line);
  Status longBinary(uint64_t n);
  Status global(const std::string& module, const std::string& name);
  Status persistentId(uint8_t op);
  Status build(Ref target, Ref state);
  Status appendItems(Ref target, const std::vector<Ref>& items);
  Status setItems(Ref target, const std::vector<Ref>& items);

  Error fail(const std::string& message) const { return heap_.fail(message); }
  // REDUCE of torch.storage._load_from_bytes runs pickles of its own (limits_).
  bool isLoadFromBytes(Ref r) const {
    const PyObj& o = heap_.at(r);
    return o.kind == Kind::Global && o.global == GlobalId::TorchLoadFromBytes;
  }

  Heap& heap_;
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  size_t op_pos_ = 0;
  const PickleLimits& limits_;
  std::vector<Ref> stack_;
  std::vector<size_t> marks_;
  std::unordered_map<uint64_t, Ref> memo_;
  bool stopped_ = false;
  Ref result_ = 0;
};

// ---- input ---------------------------------------------------------------

Status Vm::need(uint64_t n) {
  if (n > size_ - pos_) {
    return fail("unexpected end of data at byte " + std::to_string(size_) + " (opcode at byte " +
                std::to_string(op_pos_) + " needs " + std::to_string(n) + " more bytes)");
  }
  return Status::success();
}

Result<uint64_t> Vm::readUint(int bytes) {
  PK_TRY(need(bytes));
  uint64_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | data_[pos_ + k];
  pos_ += bytes;
  return v;
}

Result<std::string> Vm::readLine() {
  const void* nl = std::memchr(data_ + pos_, '\n', size_ - pos_);
  if (!nl) {
    return fail("unexpected end of data at byte " + std::to_string(size_) +
                " (text opcode at byte " + std::to_string(op_pos_) + " has no newline)");
  }
  size_t end = static_cast<const uint8_t*>(nl) - data_;
  std::string line(reinterpret_cast<const char*>(data_ + pos_), end - pos_);
  pos_ = end + 1;
  return line;
}

// Hostile lengths (2^62) are refused here, before anything is allocated.
Status Vm::checkPayload(uint64_t n, const char* what) {
  if (n > size_ - pos_) {
    return fail(std::string(what) + " length " + std::to_string(n) + " exceeds the " +
                std::to_string(size_ - pos_) + " bytes left at byte " + std::to_string(pos_));
  }
  return heap_.charge(n, what);
}

std::string Vm::take(size_t n) {
  std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
  pos_ += n;
  return s;
}

// ---- stack ---------------------------------------------------------------

Status Vm::push(Ref r) {
  if (stack_.size() >= limits_.max_stack_depth) {
    return fail("stack depth exceeds limit of " + std::to_string(limits_.max_stack_depth));
  }
  stack_.push_back(r);
  return Status::success();
}

Result<Ref> Vm::pop() {
  size_t floor = marks_.empty() ? 0 : marks_.back();
  if (stack_.size() <= floor) return fail("stack underflow at byte " + std::to_string(op_pos_));
  Ref r = stack_.back();
  stack_.pop_back();
  return r;
}

Result<Ref> Vm::top() {
  size_t floor = marks_.empty() ? 0 : marks_.back();
  if (stack_.size() <= floor) return fail("stack underflow at byte " + std::to_string(op_pos_));
  return stack_.back();
}

Result<std::vector<Ref>> Vm::popMark() {
  if (marks_.empty()) return fail("no MARK for the opcode at byte " + std::to_string(op_pos_));
  size_t m = marks_.back();
  marks_.pop_back();
  std::vector<Ref> items(stack_.begin() + m, stack_.end());
  stack_.resize(m);
  return items;
}

Status Vm::pushNew(PyObj obj) {
  Result<Ref> r = make(std::move(obj));
  if (!r) return r.error();
  return push(*r);
}

Status Vm::pushInt(int64_t v, Kind kind) {
  PyObj o;
  o.kind = kind;
  o.i = v;
  return pushNew(std::move(o));
}

Status Vm::pushFloat(double v, std::string exact) {
  PyObj o;
  o.kind = Kind::Float;
  o.f = v;
  o.exact = std::move(exact);
  return pushNew(std::move(o));
}

Status Vm::pushString(std::string s, Kind kind) {
  PyObj o;
  o.kind = kind;
  o.text = std::move(s);
  return pushNew(std::move(o));
}

Status Vm::pushContainer(Kind kind, std::vector<Ref> items) {
  PK_TRY(heap_.charge(items.size() * sizeof(Ref), "container"));
  PyObj o;
  o.kind = kind;
  o.items = std::move(items);
  return pushNew(std::move(o));
}

// ---- memo ----------------------------------------------------------------

Status Vm::memoPut(uint64_t index) {
  Result<Ref> r = top();
  if (!r) return r.error();
  if (memo_.size() >= limits_.max_memo && !memo_.count(index)) {
    return fail("memo exceeds limit of " + std::to_string(limits_.max_memo) + " entries");
  }
  memo_[index] = *r;
  return Status::success();
}

Status Vm::memoGet(uint64_t index) {
  auto it = memo_.find(index);
  if (it == memo_.end()) {
    return fail("memo index " + std::to_string(index) + " not defined (byte " +
                std::to_string(op_pos_) + ")");
  }
  return push(it->second);
}

// ---- main loop -----------------------------------------------------------

Result<Ref> Vm::run() {
  while (!stopped_) {
    op_pos_ = pos_;
    PK_TRY(need(1));
    uint8_t op = data_[pos_++];
    PK_TRY(step(op));
  }
  return result_;
}

Status Vm::step(uint8_t op) {
  bool handled = false;
  PK_TRY(stepBinary(op, &handled));
  if (!handled) PK_TRY(stepText(op, &handled));
  if (!handled) PK_TRY(stepContainers(op, &handled));
  if (!handled) PK_TRY(stepMemo(op, &handled));
  if (!handled) PK_TRY(stepObjects(op, &handled));
  if (!handled) {
    char hex[8];
    std::snprintf(hex, sizeof(hex), "0x%02x", op);
    return fail(std::string("unknown pickle opcode ") + hex + " at byte " +
                std::to_string(op_pos_));
  }
  return Status::success();
}

// ---- opcodes ---------------------------------------------------------------

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "-007" -> "-7", "-0" -> "0": the text Python's str() gives the int.
std::string canonicalDecimal(const std::string& s) {
  const bool negative = !s.empty() && s[0] == '-';
  size_t b = negative ? 1 : 0;
  while (b + 1 < s.size() && s[b] == '0') ++b;
  std::string digits = s.substr(b);
  return negative && digits != "0" ? "-" + digits : digits;
}

std::string trimmed(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// Decimal integer as Python's int() reads it; false if not a number.
bool parseDecimal(const std::string& text, int64_t* out, double* approx, bool* fits) {
  std::string s = trimmed(text);
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  if (s.empty()) return false;
  size_t digits_from = s[0] == '-' ? 1 : 0;
  if (digits_from == s.size()) return false;
  for (size_t k = digits_from; k < s.size(); ++k) {
    if (s[k] < '0' || s[k] > '9') return false;
  }
  auto r = std::from_chars(s.data(), s.data() + s.size(), *out);
  *fits = r.ec == std::errc();
  if (!*fits) {
    double v = 0;
    for (size_t k = digits_from; k < s.size(); ++k) v = v * 10 + (s[k] - '0');
    *approx = digits_from ? -v : v;
  }
  return true;
}

Status Vm::textInt(const std::string& line, bool is_long) {
  std::string s = trimmed(line);
  if (!is_long && (s == "00" || s == "01")) return pushInt(s == "01", Kind::Bool);
  if (is_long && !s.empty() && s.back() == 'L') s.pop_back();
  int64_t v = 0;
  double approx = 0;
  bool fits = true;
  if (!parseDecimal(s, &v, &approx, &fits)) {
    return fail(std::string(is_long ? "LONG" : "INT") + " opcode at byte " +
                std::to_string(op_pos_) + " has a bad value");
  }
  // Integers beyond 64 bits appear in no model file: a number keeps them
  // approximately, a dict key (a track id) by their exact text.
  return fits ? pushInt(v) : pushFloat(approx, canonicalDecimal(s));
}

Status Vm::textFloat(const std::string& line) {
  std::string s = trimmed(line);
  if (!s.empty() && s[0] == '+') s.erase(0, 1);
  double v = 0;
#ifdef __EMSCRIPTEN__
  // emscripten 3.1.6's libc++ has no floating-point from_chars: strtod (the
  // "C" locale, correctly rounded as from_chars), without hex floats.
  char* end = nullptr;
  const bool hex = s.find_first_of("xX") != std::string::npos;
  errno = 0;
  if (!s.empty() && !hex) v = std::strtod(s.c_str(), &end);
  const bool bad = s.empty() || hex || end != s.c_str() + s.size() || errno == ERANGE;
#else
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  const bool bad = s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size();
#endif
  if (bad) {
    return fail("FLOAT opcode at byte " + std::to_string(op_pos_) + " has a bad value");
  }
  return pushFloat(v);
}

// Protocol 0 STRING: a quoted Python 2 str literal with backslash escapes.
Status Vm::textString(const std::string& line) {
  std::string s = line;
  if (!s.empty() && s.back() == '\r') s.pop_back();
  if (s.size() < 2 || s.front() != s.back() || (s[0] != '\'' && s[0] != '"')) {
    return fail("STRING opcode at byte " + std::to_string(op_pos_) + " is not quoted");
  }
  std::string out;
  const size_t end = s.size() - 1;
  for (size_t k = 1; k < end; ++k) {
    char c = s[k];
    if (c != '\\' || k + 1 >= end) {
      out.push_back(c);
      continue;
    }
    char e = s[++k];
    switch (e) {
      case 'n':
        out.push_back('\n');
        break;
      case 't':
        out.push_back('\t');
        break;
      case 'r':
        out.push_back('\r');
        break;
      case 'a':
        out.push_back('\a');
        break;
      case 'b':
        out.push_back('\b');
        break;
      case 'f':
        out.push_back('\f');
        break;
      case 'v':
        out.push_back('\v');
        break;
      case '\\':
      case '\'':
      case '"':
        out.push_back(e);
        break;
      case '\n':
        break;
      case 'x': {
        int hi = k + 1 < end ? hexDigit(s[k + 1]) : -1;
        int lo = k + 2 < end ? hexDigit(s[k + 2]) : -1;
        if (hi < 0 || lo < 0) {
          return fail("STRING opcode at byte " + std::to_string(op_pos_) + " has a bad \\x escape");
        }
        out.push_back(static_cast<char>(hi * 16 + lo));
        k += 2;
        break;
      }
      default:
        if (e >= '0' && e <= '7') {
          int v = e - '0';
          for (int d = 0; d < 2 && k + 1 < end && s[k + 1] >= '0' && s[k + 1] <= '7'; ++d) {
            v = v * 8 + (s[++k] - '0');
          }
          out.push_back(static_cast<char>(v & 0xFF));
        } else {
          out.push_back('\\');
          out.push_back(e);
        }
    }
  }
  PK_TRY(heap_.charge(out.size(), "STRING"));
  return pushString(std::move(out), Kind::Bytes);
}

// Protocol 0 UNICODE: raw-unicode-escape, i.e. latin-1 bytes plus \uXXXX and
// \UXXXXXXXX escapes. Stored as UTF-8.
Status Vm::textUnicode(const std::string& line) {
  std::string out;
  for (size_t k = 0; k < line.size(); ++k) {
    unsigned char c = static_cast<unsigned char>(line[k]);
    size_t digits = 0;
    if (c == '\\' && k + 1 < line.size())
      digits = line[k + 1] == 'u' ? 4 : line[k + 1] == 'U' ? 8 : 0;
    if (!digits) {
      appendUtf8(&out, c);
      continue;
    }
    if (k + 1 + digits >= line.size()) {
      return fail("UNICODE opcode at byte " + std::to_string(op_pos_) + " has a truncated escape");
    }
    uint32_t cp = 0;
    for (size_t d = 0; d < digits; ++d) {
      int h = hexDigit(line[k + 2 + d]);
      if (h < 0)
        return fail("UNICODE opcode at byte " + std::to_string(op_pos_) + " has a bad escape");
      cp = cp * 16 + h;
    }
    if (cp > 0x10FFFF)
      return fail("UNICODE opcode at byte " + std::to_string(op_pos_) + " has a bad code point");
    appendUtf8(&out, cp);
    k += 1 + digits;
  }
  PK_TRY(heap_.charge(out.size(), "UNICODE"));
  return pushString(std::move(out), Kind::Str);
}

// LONG1/LONG4: little-endian two's complement of n bytes.
Status Vm::longBinary(uint64_t n) {
  PK_TRY(checkPayload(n, "LONG"));
  const uint8_t* p = data_ + pos_;
  pos_ += n;
  if (n == 0) return pushInt(0);
  bool negative = p[n - 1] & 0x80;
  if (n <= 8) {
    uint64_t v = 0;
    for (size_t k = n; k-- > 0;) v = (v << 8) | p[k];
    if (negative && n < 8) v |= ~uint64_t(0) << (8 * n);
    return pushInt(static_cast<int64_t>(v));
  }
  double v = 0;  // beyond 64 bits: approximate (no model file has such ints), exact as a key
  for (size_t k = n; k-- > 0;) v = v * 256 + (negative ? 255 - p[k] : p[k]);
  return pushFloat(negative ? -(v + 1) : v, exactDecimal(p, n, true));
}

Status Vm::stepBinary(uint8_t op, bool* handled) {
  *handled = true;
  switch (op) {
    case 0x80: {  // PROTO
      Result<uint64_t> v = readUint(1);
      if (!v) return v.error();
      if (*v > 5) return fail("unsupported pickle protocol " + std::to_string(*v));
      return Status::success();
    }
    case 0x95: {  // FRAME: framing only groups reads; its length must fit
      Result<uint64_t> n = readUint(8);
      if (!n) return n.error();
      if (*n > size_ - pos_) {
        return fail("FRAME length " + std::to_string(*n) + " exceeds the " +
                    std::to_string(size_ - pos_) + " bytes left at byte " + std::to_string(pos_));
      }
      return Status::success();
    }
    case '.': {  // STOP
      Result<Ref> r = pop();
      if (!r) return r.error();
      if (!marks_.empty())
        return fail("unbalanced MARK at STOP (byte " + std::to_string(op_pos_) + ")");
      result_ = *r;
      stopped_ = true;
      return Status::success();
    }
    case 'N':
      return push(0);
    case 0x88:
      return pushInt(1, Kind::Bool);
    case 0x89:
      return pushInt(0, Kind::Bool);
    case 'J': {
      Result<uint64_t> v = readUint(4);
      if (!v) return v.error();
      return pushInt(static_cast<int32_t>(static_cast<uint32_t>(*v)));
    }
    case 'K':
    case 'M': {
      Result<uint64_t> v = readUint(op == 'K' ? 1 : 2);
      if (!v) return v.error();
      return pushInt(static_cast<int64_t>(*v));
    }
    case 0x8a:
    case 0x8b: {  // LONG1, LONG4
      Result<uint64_t> n = readUint(op == 0x8a ? 1 : 4);
      if (!n) return n.error();
      return longBinary(*n);
    }
    case 'G': {  // BINFLOAT: big-endian double
      PK_TRY(need(8));
      uint64_t bits = 0;
      for (int k = 0; k < 8; ++k) bits = (bits << 8) | data_[pos_ + k];
      pos_ += 8;
      double v;
      std::memcpy(&v, &bits, 8);
      return pushFloat(v);
    }
    default:
      return stepPayload(op, handled);
  }
}

// Length-prefixed strings and bytes, and the opcodes refused outright.
Status Vm::stepPayload(uint8_t op, bool* handled) {
  int len_bytes = 0;
  Kind kind = Kind::Bytes;
  const char* name = "";
  switch (op) {
    case 'U':
      len_bytes = 1;
      name = "SHORT_BINSTRING";
      break;
    case 'T':
      len_bytes = 4;
      name = "BINSTRING";
      break;
    case 'C':
      len_bytes = 1;
      name = "SHORT_BINBYTES";
      break;
    case 'B':
      len_bytes = 4;
      name = "BINBYTES";
      break;
    case 0x8e:
      len_bytes = 8;
      name = "BINBYTES8";
      break;
    case 0x96:
      len_bytes = 8;
      name = "BYTEARRAY8";
      break;
    case 0x8c:
      len_bytes = 1;
      kind = Kind::Str;
      name = "SHORT_BINUNICODE";
      break;
    case 'X':
      len_bytes = 4;
      kind = Kind::Str;
      name = "BINUNICODE";
      break;
    case 0x8d:
      len_bytes = 8;
      kind = Kind::Str;
      name = "BINUNICODE8";
      break;
    case 0x97:
    case 0x98:
      return fail("out-of-band pickle buffers are not supported");
    case 'P':
    case 'Q':
      return persistentId(op);
    case 0x82:
    case 0x83:
    case 0x84:
      return fail("pickle extension codes are not supported");
    default:
      *handled = false;
      return Status::success();
  }
  Result<uint64_t> n = readUint(len_bytes);
  if (!n) return n.error();
  if (op == 'T' && (*n & 0x80000000u)) return fail("BINSTRING has a negative length");
  PK_TRY(checkPayload(*n, name));
  if (kind == Kind::Bytes && *n >= kViewBytes) {  // array payloads: no copy (PyObj::view)
    PyObj o;
    o.kind = kind;
    o.view = reinterpret_cast<const char*>(data_ + pos_);
    o.view_size = static_cast<size_t>(*n);
    pos_ += o.view_size;
    return pushNew(std::move(o));
  }
  return pushString(take(static_cast<size_t>(*n)), kind);
}

Status Vm::stepText(uint8_t op, bool* handled) {
  if (op != 'I' && op != 'L' && op != 'F' && op != 'S' && op != 'V') {
    *handled = false;
    return Status::success();
  }
  *handled = true;
  Result<std::string> line = readLine();
  if (!line) return line.error();
  switch (op) {
    case 'I':
      return textInt(*line, false);
    case 'L':
      return textInt(*line, true);
    case 'F':
      return textFloat(*line);
    case 'S':
      return textString(*line);
    default:
      return textUnicode(*line);
  }
}

Status Vm::appendItems(Ref target, const std::vector<Ref>& items) {
  PyObj& t = heap_.at(target);
  if (t.kind != Kind::List)
    return fail("APPEND to a " + typeName(heap_, target) + " is not supported");
  PK_TRY(heap_.charge(items.size() * sizeof(Ref), "list"));
  t.items.insert(t.items.end(), items.begin(), items.end());
  return Status::success();
}

Status Vm::setItems(Ref target, const std::vector<Ref>& items) {
  PyObj& t = heap_.at(target);
  if (t.kind != Kind::Dict)
    return fail("SETITEM on a " + typeName(heap_, target) + " is not supported");
  if (items.size() % 2)
    return fail("SETITEMS with an odd number of items at byte " + std::to_string(op_pos_));
  PK_TRY(heap_.charge(items.size() * sizeof(Ref), "dict"));
  t.items.insert(t.items.end(), items.begin(), items.end());
  return Status::success();
}

Status Vm::stepContainers(uint8_t op, bool* handled) {
  *handled = true;
  switch (op) {
    case '(':
      if (marks_.size() >= limits_.max_stack_depth) {
        return fail("MARK nesting exceeds limit of " + std::to_string(limits_.max_stack_depth));
      }
      marks_.push_back(stack_.size());
      return Status::success();
    case '0': {  // POP: an empty frame pops its MARK, as Python does
      size_t floor = marks_.empty() ? 0 : marks_.back();
      if (stack_.size() > floor) {
        stack_.pop_back();
        return Status::success();
      }
      Result<std::vector<Ref>> m = popMark();
      return m ? Status::success() : Status(m.error());
    }
    case '1': {
      Result<std::vector<Ref>> m = popMark();
      return m ? Status::success() : Status(m.error());
    }
    case '2': {
      Result<Ref> r = top();
      if (!r) return r.error();
      return push(*r);
    }
    case ']':
      return pushContainer(Kind::List, {});
    case ')':
      return pushContainer(Kind::Tuple, {});
    case '}':
      return pushContainer(Kind::Dict, {});
    case 0x8f:
      return pushContainer(Kind::Set, {});
    case 0x85:
    case 0x86:
    case 0x87: {
      std::vector<Ref> items(op - 0x84);
      for (size_t k = items.size(); k-- > 0;) {
        Result<Ref> r = pop();
        if (!r) return r.error();
        items[k] = *r;
      }
      return pushContainer(Kind::Tuple, std::move(items));
    }
    default:
      break;
  }
  if (op == 'a' || op == 's') {
    std::vector<Ref> items(op == 'a' ? 1 : 2);
    for (size_t k = items.size(); k-- > 0;) {
      Result<Ref> r = pop();
      if (!r) return r.error();
      items[k] = *r;
    }
    Result<Ref> t = top();
    if (!t) return t.error();
    return op == 'a' ? appendItems(*t, items) : setItems(*t, items);
  }
  if (op != 'l' && op != 't' && op != 'd' && op != 0x91 && op != 'e' && op != 'u' && op != 0x90) {
    *handled = false;
    return Status::success();
  }
  Result<std::vector<Ref>> items = popMark();
  if (!items) return items.error();
  switch (op) {
    case 'l':
      return pushContainer(Kind::List, std::move(*items));
    case 't':
      return pushContainer(Kind::Tuple, std::move(*items));
    case 0x91:
      return pushContainer(Kind::Set, std::move(*items));
    case 'd': {
      if (items->size() % 2)
        return fail("DICT with an odd number of items at byte " + std::to_string(op_pos_));
      return pushContainer(Kind::Dict, std::move(*items));
    }
    default:
      break;
  }
  Result<Ref> t = top();
  if (!t) return t.error();
  if (op == 'e') return appendItems(*t, *items);
  if (op == 'u') return setItems(*t, *items);
  PyObj& set = heap_.at(*t);  // ADDITEMS
  if (set.kind != Kind::Set)
    return fail("ADDITEMS to a " + typeName(heap_, *t) + " is not supported");
  PK_TRY(heap_.charge(items->size() * sizeof(Ref), "set"));
  set.items.insert(set.items.end(), items->begin(), items->end());
  return Status::success();
}

Status Vm::stepMemo(uint8_t op, bool* handled) {
  *handled = true;
  switch (op) {
    case 'p':
    case 'g': {
      Result<std::string> line = readLine();
      if (!line) return line.error();
      int64_t v = 0;
      double approx = 0;
      bool fits = true;
      if (!parseDecimal(*line, &v, &approx, &fits) || !fits || v < 0) {
        return fail(std::string(op == 'p' ? "PUT" : "GET") + " at byte " + std::to_string(op_pos_) +
                    " has a bad memo index");
      }
      return op == 'p' ? memoPut(static_cast<uint64_t>(v)) : memoGet(static_cast<uint64_t>(v));
    }
    case 'q':
    case 'r':
    case 'h':
    case 'j': {
      Result<uint64_t> v = readUint(op == 'q' || op == 'h' ? 1 : 4);
      if (!v) return v.error();
      return op == 'q' || op == 'r' ? memoPut(*v) : memoGet(*v);
    }
    case 0x94:
      return memoPut(memo_.size());
    default:
      *handled = false;
      return Status::success();
  }
}

Status Vm::global(const std::string& module, const std::string& name) {
  Result<GlobalId> id = resolveGlobal(heap_, module, name);
  if (!id) return id.error();
  PyObj o;
  o.kind = Kind::Global;
  o.global = *id;
  o.text = module + "." + name;
  return pushNew(std::move(o));
}

// PERSID / BINPERSID: only torch names its storages this way (in a .pt
// archive, and inside the bytes of torch.storage._load_from_bytes).
Status Vm::persistentId(uint8_t op) {
  const VmOptions& options = heap_.options();
  if ((!options.torch_storage && !options.legacy_storages) || op == 'P')
    return fail("persistent IDs are not supported (not model data)");
  Result<Ref> pid = pop();
  if (!pid) return pid.error();
  Result<Ref> storage =
      options.legacy_storages ? legacyPersistentLoad(heap_, *pid) : persistentLoad(heap_, *pid);
  if (!storage) return storage.error();
  return push(*storage);
}

// BUILD; joblib writes a NumpyArrayWrapper's array bytes right after it.
Status Vm::build(Ref target, Ref state) {
  PK_TRY(buildObject(heap_, target, state));
  const PyObj& o = heap_.at(target);
  if (o.kind != Kind::Instance || o.global != GlobalId::JoblibWrapper) return Status::success();
  return readJoblibArray(heap_, target, data_, size_, &pos_, limits_);
}

Status Vm::stepObjects(uint8_t op, bool* handled) {
  *handled = true;
  switch (op) {
    case 'c':
    case 'i': {  // GLOBAL, INST: "module\nname\n"
      Result<std::string> module = readLine();
      if (!module) return module.error();
      Result<std::string> name = readLine();
      if (!name) return name.error();
      PK_TRY(global(trimmed(*module), trimmed(*name)));
      if (op == 'c') return Status::success();
      Result<Ref> cls = pop();
      if (!cls) return cls.error();
      Result<std::vector<Ref>> args = popMark();
      if (!args) return args.error();
      Result<Ref> tuple = makeTuple(std::move(*args));
      if (!tuple) return tuple.error();
      Result<Ref> obj = callGlobal(heap_, *cls, *tuple);
      if (!obj) return obj.error();
      return push(*obj);
    }
    case 0x93: {  // STACK_GLOBAL
      Result<Ref> name = pop();
      if (!name) return name.error();
      Result<Ref> module = pop();
      if (!module) return module.error();
      if (heap_.at(*name).kind != Kind::Str || heap_.at(*module).kind != Kind::Str) {
        return fail("STACK_GLOBAL needs two str at byte " + std::to_string(op_pos_));
      }
      return global(heap_.at(*module).text, heap_.at(*name).text);
    }
    case 'o': {  // OBJ: MARK cls args...
      Result<std::vector<Ref>> items = popMark();
      if (!items) return items.error();
      if (items->empty()) return fail("OBJ without a class at byte " + std::to_string(op_pos_));
      Ref cls = items->front();
      std::vector<Ref> args(items->begin() + 1, items->end());
      Result<Ref> tuple = makeTuple(std::move(args));
      if (!tuple) return tuple.error();
      Result<Ref> obj = callGlobal(heap_, cls, *tuple);
      if (!obj) return obj.error();
      return push(*obj);
    }
    default:
      break;
  }
  if (op != 'R' && op != 'b' && op != 0x81 && op != 0x92) {
    *handled = false;
    return Status::success();
  }
  if (op == 0x92) {  // NEWOBJ_EX: keyword arguments play no part for allowed classes
    Result<Ref> kwargs = pop();
    if (!kwargs) return kwargs.error();
  }
  Result<Ref> arg = pop();
  if (!arg) return arg.error();
  Result<Ref> target = op == 'b' ? top() : pop();
  if (!target) return target.error();
  if (op == 'b') return build(*target, *arg);
  Result<Ref> obj = op != 'R'                  ? newObject(heap_, *target, *arg)
                    : isLoadFromBytes(*target) ? loadFromBytes(heap_, *arg, limits_)
                                               : callGlobal(heap_, *target, *arg);
  if (!obj) return obj.error();
  return push(*obj);
}

}  // namespace

std::string exactDecimal(const uint8_t* bytes, size_t n, bool is_signed) {
  const bool negative = is_signed && n > 0 && (bytes[n - 1] & 0x80);
  // Magnitude, big-endian: two's complement negated (invert, add one).
  std::vector<uint8_t> mag(n);
  for (size_t k = 0; k < n; ++k) mag[n - 1 - k] = negative ? uint8_t(~bytes[k]) : bytes[k];
  for (size_t k = n; negative && k-- > 0;)
    if (++mag[k] != 0) break;
  if (n > kMaxExactIntBytes) {  // hex: linear, still exact and distinct from every decimal
    static const char kHex[] = "0123456789abcdef";
    std::string hex;
    for (uint8_t b : mag)
      if (!hex.empty() || b != 0) hex += {kHex[b >> 4], kHex[b & 15]};
    while (hex.size() > 1 && hex[0] == '0') hex.erase(0, 1);
    return (negative ? "-0x" : "0x") + (hex.empty() ? std::string("0") : hex);
  }
  std::string digits;  // least significant first: repeated division by 10
  for (size_t first = 0; first < n;) {
    unsigned rest = 0;
    for (size_t k = first; k < n; ++k) {
      const unsigned cur = (rest << 8) | mag[k];
      mag[k] = static_cast<uint8_t>(cur / 10);
      rest = cur % 10;
    }
    digits.push_back(static_cast<char>('0' + rest));
    while (first < n && mag[first] == 0) ++first;
  }
  if (digits.empty()) digits = "0";
  if (negative) digits.push_back('-');
  return std::string(digits.rbegin(), digits.rend());
}

Result<Ref> runPickle(Heap& heap, const uint8_t* data, size_t size, const PickleLimits& limits) {
  Vm vm(heap, data, size, 0, limits);
  return vm.run();
}

Result<Ref> runPickleAt(Heap& heap, const uint8_t* data, size_t size, size_t start,
                        const PickleLimits& limits, size_t* end) {
  Vm vm(heap, data, size, start, limits);
  Result<Ref> r = vm.run();
  *end = vm.position();
  return r;
}

}  // namespace pickle
}  // namespace smpl
