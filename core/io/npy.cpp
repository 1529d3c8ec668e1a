// .npy reader. Layout (numpy/lib/format.py): magic "\x93NUMPY", major, minor,
// header length (uint16 LE for v1, uint32 LE for v2/v3), then a Python dict
// literal {'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), } padded
// with spaces and '\n', then the raw elements. The header is parsed here by a
// small strict literal parser (no eval), and every size is checked before any
// allocation: the element count must fit the bytes actually present.
#include "core/io/npy.h"

#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "core/io/file_io.h"
#include "core/io/numpy_dtype.h"
#include "core/io/printable.h"

namespace smpl {
namespace {

constexpr size_t kMagicBytes = 6;
constexpr size_t kMaxHeaderBytes = 1 << 20;  // numpy itself refuses > 10000 by default
constexpr size_t kMaxDims = 64;              // numpy's NPY_MAXDIMS (2.x); 1.x uses 32

struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<int64_t> shape;
  bool has_descr = false, has_order = false, has_shape = false;
};

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
    return makeError(ctx + ": bad .npy header: unexpected or repeated key '" + printable(key, 64) +
                     "'");
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
    if (!c.eat(':'))
      return makeError(ctx + ": bad .npy header: expected ':' after '" + printable(*key, 64) + "'");
    if (Status st = parseHeaderValue(c, *key, h, ctx); !st) return st.error();
    if (!c.eat(',') && !c.peek('}'))
      return makeError(ctx + ": bad .npy header: expected ',' or '}' after '" +
                       printable(*key, 64) + "'");
  }
  c.skipSpace();
  if (c.pos != text.size())
    return makeError(ctx + ": bad .npy header: trailing characters after the dict");
  if (!h.has_descr || !h.has_order || !h.has_shape)
    return makeError(ctx + ": bad .npy header: needs 'descr', 'fortran_order' and 'shape'");
  return h;
}

// ---- preamble ----------------------------------------------------------------

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

}  // namespace

Result<NpyHeaderInfo> parseNpyHeader(const uint8_t* data, size_t size, const std::string& context) {
  if (data == nullptr && size != 0) return makeError(context + ": no data");
  NpyHeaderInfo info;
  Result<std::string> text = readPreamble(data, size, context, info.data_offset);
  if (!text) return text.error();
  Result<NpyHeader> h = parseHeaderDict(*text, context);
  if (!h) return h.error();
  info.descr = h->descr;
  info.fortran_order = h->fortran_order;
  info.shape = std::move(h->shape);
  return info;
}

bool isObjectDescr(const std::string& descr) {
  return descr.size() == 2 && (descr[0] == '|' || descr[0] == '<' || descr[0] == '>') &&
         descr[1] == 'O';
}

Result<Array> parseNpy(const uint8_t* data, size_t size, const std::string& context) {
  Result<NpyHeaderInfo> h = parseNpyHeader(data, size, context);
  if (!h) return h.error();
  const size_t offset = h->data_offset;
  Result<NumpyDtype> t = parseNumpyDescr(h->descr, context);
  if (!t) return t.error();
  Result<size_t> need = numpyByteCount(*t, h->shape, context);
  if (!need) return need.error();
  const size_t have = size - offset;
  if (have < *need)
    return makeError(context + ": truncated data: expected " + std::to_string(*need) +
                     " bytes, found " + std::to_string(have));
  // Like numpy.load, read the bytes the header promises and ignore any after them.
  return decodeNumpyArray(data + offset, *need, *t, h->shape, h->fortran_order, context);
}

Result<Array> readNpyFile(const std::string& path, const InputKind& kind) {
  Result<std::vector<uint8_t>> bytes = readFileBytes(path, kind);
  if (!bytes) return bytes.error();
  return parseNpy(bytes->data(), bytes->size(), baseName(path));
}

}  // namespace smpl
