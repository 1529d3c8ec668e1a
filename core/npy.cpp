// .npy reader. Layout (numpy/lib/format.py): magic "\x93NUMPY", major, minor,
// header length (uint16 LE for v1, uint32 LE for v2/v3), then a Python dict
// literal {'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), } padded
// with spaces and '\n', then the raw elements. The header is parsed here by a
// small strict literal parser (no eval), and every size is checked before any
// allocation: the element count must fit the bytes actually present.
#include "core/npy.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "core/file_io.h"

namespace smpl {
namespace {

constexpr size_t kMagicBytes = 6;
constexpr size_t kMaxHeaderBytes = 1 << 20;  // numpy itself refuses > 10000 by default
constexpr size_t kMaxDims = 64;              // numpy's NPY_MAXDIMS (2.x); 1.x uses 32
constexpr size_t kMaxStringChars = 1 << 26;  // characters per string element

struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<int64_t> shape;
  bool has_descr = false, has_order = false, has_shape = false;
};

// Element type decoded from a descr such as "<f8" or "|S6".
struct DType {
  char kind = 0;        // 'f', 'i', 'u', 'b', 'U', 'S'
  size_t itemsize = 0;  // bytes per element
  bool big_endian = false;
};

bool hostIsBigEndian() {
  const uint16_t one = 1;
  uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

// ---- header dict: a Python literal with string keys ----------------------

struct Cursor {
  const std::string& s;
  size_t pos = 0;
  void skipSpace() {
    while (pos < s.size() && (s[pos] == ' ' || s[pos] == '\t' || s[pos] == '\n' || s[pos] == '\r'))
      ++pos;
  }
  bool eat(char c) {
    skipSpace();
    if (pos < s.size() && s[pos] == c) return ++pos, true;
    return false;
  }
  bool peek(char c) {
    skipSpace();
    return pos < s.size() && s[pos] == c;
  }
  bool eatWord(const char* w) {
    skipSpace();
    size_t n = std::strlen(w);
    if (s.compare(pos, n, w) != 0) return false;
    pos += n;
    return true;
  }
};

Result<std::string> parseQuoted(Cursor& c, const std::string& ctx) {
  c.skipSpace();
  if (c.pos >= c.s.size() || (c.s[c.pos] != '\'' && c.s[c.pos] != '"'))
    return makeError(ctx + ": bad .npy header: expected a quoted string at offset " +
                     std::to_string(c.pos));
  const char quote = c.s[c.pos++];
  size_t end = c.s.find(quote, c.pos);
  if (end == std::string::npos) return makeError(ctx + ": bad .npy header: unterminated string");
  std::string out = c.s.substr(c.pos, end - c.pos);
  if (out.find('\\') != std::string::npos)
    return makeError(ctx + ": bad .npy header: escapes in strings are not supported");
  c.pos = end + 1;
  return out;
}

// One dimension: decimal digits, optionally with Python 2's 'L' suffix.
Result<int64_t> parseDim(Cursor& c, const std::string& ctx) {
  c.skipSpace();
  if (c.pos < c.s.size() && c.s[c.pos] == '-')
    return makeError(ctx + ": bad .npy header: negative dimension in shape");
  int64_t v = 0;
  size_t start = c.pos;
  for (; c.pos < c.s.size() && c.s[c.pos] >= '0' && c.s[c.pos] <= '9'; ++c.pos) {
    if (v > (std::numeric_limits<int64_t>::max() - 9) / 10)
      return makeError(ctx + ": bad .npy header: dimension too large");
    v = v * 10 + (c.s[c.pos] - '0');
  }
  if (c.pos == start)
    return makeError(ctx + ": bad .npy header: expected a dimension at offset " +
                     std::to_string(start));
  if (c.pos < c.s.size() && c.s[c.pos] == 'L') ++c.pos;
  return v;
}

// "()", "(3,)", "(3, 4)", "(3, 4,)".
Result<std::vector<int64_t>> parseShape(Cursor& c, const std::string& ctx) {
  if (!c.eat('(')) return makeError(ctx + ": bad .npy header: 'shape' must be a tuple");
  std::vector<int64_t> shape;
  while (!c.eat(')')) {
    if (shape.size() == kMaxDims)
      return makeError(ctx + ": bad .npy header: more than 64 dimensions");
    Result<int64_t> d = parseDim(c, ctx);
    if (!d) return d.error();
    shape.push_back(*d);
    if (!c.eat(',') && !c.peek(')'))
      return makeError(ctx + ": bad .npy header: malformed 'shape' tuple");
  }
  return shape;
}

Status parseHeaderValue(Cursor& c, const std::string& key, NpyHeader& h, const std::string& ctx) {
  if (key == "descr" && !h.has_descr) {
    if (c.peek('['))
      return makeError(ctx + ": structured dtypes (record arrays) are not supported");
    Result<std::string> d = parseQuoted(c, ctx);
    if (!d) return d.error();
    h.descr = *d;
    h.has_descr = true;
  } else if (key == "fortran_order" && !h.has_order) {
    if (c.eatWord("True"))
      h.fortran_order = true;
    else if (c.eatWord("False"))
      h.fortran_order = false;
    else
      return makeError(ctx + ": bad .npy header: 'fortran_order' must be True or False");
    h.has_order = true;
  } else if (key == "shape" && !h.has_shape) {
    Result<std::vector<int64_t>> s = parseShape(c, ctx);
    if (!s) return s.error();
    h.shape = std::move(*s);
    h.has_shape = true;
  } else {
    return makeError(ctx + ": bad .npy header: unexpected or repeated key '" + key + "'");
  }
  return Status();
}

Result<NpyHeader> parseHeaderDict(const std::string& text, const std::string& ctx) {
  Cursor c{text};
  NpyHeader h;
  if (!c.eat('{')) return makeError(ctx + ": bad .npy header: expected a dict");
  while (!c.eat('}')) {
    Result<std::string> key = parseQuoted(c, ctx);
    if (!key) return key.error();
    if (!c.eat(':')) return makeError(ctx + ": bad .npy header: expected ':' after '" + *key + "'");
    if (Status st = parseHeaderValue(c, *key, h, ctx); !st) return st.error();
    if (!c.eat(',') && !c.peek('}'))
      return makeError(ctx + ": bad .npy header: expected ',' or '}' after '" + *key + "'");
  }
  c.skipSpace();
  if (c.pos != text.size())
    return makeError(ctx + ": bad .npy header: trailing characters after the dict");
  if (!h.has_descr || !h.has_order || !h.has_shape)
    return makeError(ctx + ": bad .npy header: needs 'descr', 'fortran_order' and 'shape'");
  return h;
}

// ---- preamble and dtype ----------------------------------------------------

// Checks magic and version; returns the header text and sets `data_offset`.
Result<std::string> readPreamble(const uint8_t* data, size_t size, const std::string& ctx,
                                 size_t& data_offset) {
  if (size < kMagicBytes + 2 || std::memcmp(data, "\x93NUMPY", kMagicBytes) != 0)
    return makeError(ctx + ": not an .npy file (bad magic)");
  const int major = data[6], minor = data[7];
  if (major < 1 || major > 3 || minor != 0)
    return makeError(ctx + ": unsupported .npy version " + std::to_string(major) + "." +
                     std::to_string(minor));
  const size_t len_bytes = major == 1 ? 2 : 4;
  if (size < 8 + len_bytes) return makeError(ctx + ": truncated .npy header");
  size_t header_len = 0;
  for (size_t i = 0; i < len_bytes; ++i) header_len |= static_cast<size_t>(data[8 + i]) << (8 * i);
  if (header_len > kMaxHeaderBytes)
    return makeError(ctx + ": bad .npy header: header length " + std::to_string(header_len) +
                     " is absurd");
  data_offset = 8 + len_bytes + header_len;
  if (data_offset > size)
    return makeError(ctx + ": truncated .npy header: expected " + std::to_string(header_len) +
                     " bytes, found " + std::to_string(size - 8 - len_bytes));
  return std::string(reinterpret_cast<const char*>(data) + 8 + len_bytes, header_len);
}

Result<size_t> descrItemCount(const std::string& digits, const std::string& descr,
                              const std::string& ctx) {
  if (digits.empty() || digits.size() > 9 ||
      digits.find_first_not_of("0123456789") != std::string::npos)
    return makeError(ctx + ": unsupported dtype '" + descr + "'");
  return static_cast<size_t>(std::stoll(digits));
}

bool validItemSize(char kind, size_t n) {
  if (kind == 'f') return n == 2 || n == 4 || n == 8;
  if (kind == 'i' || kind == 'u') return n == 1 || n == 2 || n == 4 || n == 8;
  if (kind == 'b') return n == 1;
  if (kind == 'S' || kind == 'U') return n >= 1 && n <= kMaxStringChars;
  return false;
}

Result<DType> parseDescr(const std::string& descr, const std::string& ctx) {
  if (descr.size() < 2 || std::string("<>|=").find(descr[0]) == std::string::npos)
    return makeError(ctx + ": unsupported dtype '" + descr + "'");
  const char order = descr[0], kind = descr[1];
  if (kind == 'O')
    return makeError(ctx + ": object arrays ('" + descr +
                     "') are not supported; save a numeric array");
  if (kind == 'V')
    return makeError(ctx + ": structured/void dtype '" + descr + "' is not supported");
  Result<size_t> n = descrItemCount(descr.substr(2), descr, ctx);
  if (!n) return n.error();
  // 'U' counts characters of 4-byte UTF-32 code units; all others count bytes.
  DType t{kind, kind == 'U' ? *n * 4 : *n, order == '>' || (order == '=' && hostIsBigEndian())};
  if (!validItemSize(kind, *n)) return makeError(ctx + ": unsupported dtype '" + descr + "'");
  if (order == '|' && t.itemsize > 1 && kind != 'S')
    return makeError(ctx + ": dtype '" + descr + "' needs a byte order");
  return t;
}

// Product of the dimensions, or an error if it (or its byte size) overflows.
// Dimensions are checked even when one of them is 0, so Array::size() of any
// returned array cannot overflow either.
Result<size_t> elementCount(const std::vector<int64_t>& shape, size_t itemsize,
                            const std::string& ctx) {
  const uint64_t limit = static_cast<uint64_t>(std::numeric_limits<int64_t>::max()) / itemsize;
  uint64_t nonzero = 1;
  bool empty = false;
  for (int64_t d : shape) {
    if (d == 0)
      empty = true;
    else if (static_cast<uint64_t>(d) > limit / nonzero)
      return makeError(ctx + ": shape " + shapeString(shape) + " is too large");
    else
      nonzero *= static_cast<uint64_t>(d);
  }
  if (nonzero > std::numeric_limits<size_t>::max() / itemsize)
    return makeError(ctx + ": shape " + shapeString(shape) + " is too large");
  return empty ? size_t{0} : static_cast<size_t>(nonzero);
}

// ---- element conversion ------------------------------------------------------

uint64_t loadUnsigned(const uint8_t* p, size_t n, bool big) {
  uint64_t v = 0;
  for (size_t i = 0; i < n; ++i) v |= static_cast<uint64_t>(p[big ? n - 1 - i : i]) << (8 * i);
  return v;
}

double halfToDouble(uint16_t h) {
  const int sign = h >> 15, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  double v;
  if (exponent == 0)
    v = std::ldexp(mantissa, -24);  // zero and subnormals
  else if (exponent == 31)
    v = mantissa ? std::numeric_limits<double>::quiet_NaN()
                 : std::numeric_limits<double>::infinity();
  else
    v = std::ldexp(mantissa + 1024, exponent - 25);
  return sign ? -v : v;
}

double loadNumber(const uint8_t* p, const DType& t) {
  const uint64_t bits = loadUnsigned(p, t.itemsize, t.big_endian);
  switch (t.kind) {
    case 'b':
      return bits != 0 ? 1.0 : 0.0;
    case 'u':
      return static_cast<double>(bits);
    case 'i': {
      const unsigned shift = 64 - 8 * static_cast<unsigned>(t.itemsize);
      return static_cast<double>(static_cast<int64_t>(bits << shift) >> shift);  // sign-extend
    }
    default:
      break;  // 'f'
  }
  if (t.itemsize == 2) return halfToDouble(static_cast<uint16_t>(bits));
  if (t.itemsize == 4) {
    const uint32_t b32 = static_cast<uint32_t>(bits);
    float f;
    std::memcpy(&f, &b32, 4);
    return f;
  }
  double d;
  std::memcpy(&d, &bits, 8);
  return d;
}

std::vector<double> convertNumbers(const uint8_t* p, size_t count, const DType& t) {
  std::vector<double> out(count);
  for (size_t i = 0; i < count; ++i) out[i] = loadNumber(p + i * t.itemsize, t);
  return out;
}

bool appendUtf8(uint32_t cp, std::string& out) {
  if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
  return true;
}

// numpy pads both 'S' and 'U' elements with NULs and strips them on access.
Result<std::string> convertString(const uint8_t* p, const DType& t, const std::string& ctx) {
  if (t.kind == 'S') {
    size_t n = t.itemsize;
    while (n > 0 && p[n - 1] == 0) --n;
    return std::string(reinterpret_cast<const char*>(p), n);
  }
  size_t n = t.itemsize / 4;
  while (n > 0 && loadUnsigned(p + 4 * (n - 1), 4, t.big_endian) == 0) --n;
  std::string out;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t cp = static_cast<uint32_t>(loadUnsigned(p + 4 * i, 4, t.big_endian));
    if (!appendUtf8(cp, out))
      return makeError(ctx + ": invalid unicode code point " + std::to_string(cp) + " in a string");
  }
  return out;
}

Result<std::vector<std::string>> convertStrings(const uint8_t* p, size_t count, const DType& t,
                                                const std::string& ctx) {
  std::vector<std::string> out;
  out.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    Result<std::string> s = convertString(p + i * t.itemsize, t, ctx);
    if (!s) return s.error();
    out.push_back(std::move(*s));
  }
  return out;
}

// Fortran (column-major) element order to C order: walk the C-order index
// like an odometer and track the matching Fortran offset.
template <class T>
std::vector<T> fortranToC(std::vector<T> in, const std::vector<int64_t>& shape) {
  if (shape.size() < 2 || in.empty()) return in;
  const size_t nd = shape.size();
  std::vector<size_t> stride(nd, 1), idx(nd, 0);
  for (size_t k = 1; k < nd; ++k) stride[k] = stride[k - 1] * static_cast<size_t>(shape[k - 1]);
  std::vector<T> out;
  out.reserve(in.size());
  size_t src = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    out.push_back(std::move(in[src]));
    for (size_t k = nd; k-- > 0;) {
      if (++idx[k] < static_cast<size_t>(shape[k])) {
        src += stride[k];
        break;
      }
      src -= stride[k] * (idx[k] - 1);
      idx[k] = 0;
    }
  }
  return out;
}

Status fillElements(const uint8_t* p, size_t count, const DType& t, bool fortran, Array& a,
                    const std::string& ctx) {
  if (t.kind == 'S' || t.kind == 'U') {
    Result<std::vector<std::string>> s = convertStrings(p, count, t, ctx);
    if (!s) return s.error();
    a.strings = fortran ? fortranToC(std::move(*s), a.shape) : std::move(*s);
  } else {
    std::vector<double> v = convertNumbers(p, count, t);
    a.data = fortran ? fortranToC(std::move(v), a.shape) : std::move(v);
  }
  return Status();
}

}  // namespace

Result<Array> parseNpy(const uint8_t* data, size_t size, const std::string& context) {
  if (data == nullptr && size != 0) return makeError(context + ": no data");
  size_t offset = 0;
  Result<std::string> text = readPreamble(data, size, context, offset);
  if (!text) return text.error();
  Result<NpyHeader> h = parseHeaderDict(*text, context);
  if (!h) return h.error();
  Result<DType> t = parseDescr(h->descr, context);
  if (!t) return t.error();
  Result<size_t> count = elementCount(h->shape, t->itemsize, context);
  if (!count) return count.error();
  const size_t need = *count * t->itemsize, have = size - offset;
  if (have < need)
    return makeError(context + ": truncated data: expected " + std::to_string(need) +
                     " bytes, found " + std::to_string(have));
  Array a;
  a.shape = h->shape;
  a.dtype = h->descr;
  if (Status st = fillElements(data + offset, *count, *t, h->fortran_order, a, context); !st)
    return st.error();
  return a;
}

Result<Array> readNpyFile(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  return parseNpy(bytes->data(), bytes->size(), baseName(path));
}

}  // namespace smpl
