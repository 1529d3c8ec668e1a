// numpy element decoding. Values are read byte by byte in the dtype's order,
// so the result does not depend on the host's endianness or alignment.
#include "core/io/numpy_dtype.h"

#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <utility>

#include "core/huge_pages.h"
#include "core/io/printable.h"
#include "core/utf8.h"

namespace smpl {
namespace {

constexpr size_t kMaxStringChars = 1 << 26;  // characters per string element

bool hostIsBigEndian() {
  const uint16_t one = 1;
  uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

Result<size_t> descrItemCount(const std::string& digits, const std::string& descr,
                              const std::string& ctx) {
  if (digits.empty() || digits.size() > 9 ||
      digits.find_first_not_of("0123456789") != std::string::npos)
    return makeError(ctx + ": unsupported dtype '" + printable(descr, 64) + "'");
  return static_cast<size_t>(std::stoll(digits));
}

bool validItemSize(char kind, size_t n) {
  if (kind == 'f') return n == 2 || n == 4 || n == 8;
  if (kind == 'i' || kind == 'u') return n == 1 || n == 2 || n == 4 || n == 8;
  if (kind == 'b') return n == 1;
  if (kind == 'S' || kind == 'U') return n >= 1 && n <= kMaxStringChars;
  return false;
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

double loadNumber(const uint8_t* p, const NumpyDtype& t) {
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

// numpy pads both 'S' and 'U' elements with NULs and strips them on access.
// 'U' must hold Unicode scalar values: surrogates and values past 0x10FFFF
// are refused rather than turned into invalid UTF-8.
Result<std::string> loadString(const uint8_t* p, const NumpyDtype& t, const std::string& ctx) {
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
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
      return makeError(ctx + ": invalid unicode code point " + std::to_string(cp) + " in a string");
    appendUtf8(&out, cp);
  }
  return out;
}

// Position in the payload of each element, taken in C order. Fortran
// (column-major) payloads: walk the C-order index like an odometer and track
// the matching Fortran offset, so elements are decoded straight into place.
class SourceOrder {
 public:
  SourceOrder(const std::vector<int64_t>& shape, bool fortran)
      : shape_(shape), fortran_(fortran && shape.size() > 1) {
    if (!fortran_) return;
    stride_.assign(shape.size(), 1);
    index_.assign(shape.size(), 0);
    for (size_t k = 1; k < shape.size(); ++k)
      stride_[k] = stride_[k - 1] * static_cast<size_t>(shape[k - 1]);
  }
  // Element offset of the current element; then step to the next in C order.
  size_t next() {
    const size_t current = src_;
    if (!fortran_) return src_++;
    for (size_t k = shape_.size(); k-- > 0;) {
      if (++index_[k] < static_cast<size_t>(shape_[k])) {
        src_ += stride_[k];
        break;
      }
      src_ -= stride_[k] * (index_[k] - 1);
      index_[k] = 0;
    }
    return current;
  }

 private:
  const std::vector<int64_t>& shape_;
  bool fortran_;
  std::vector<size_t> stride_, index_;
  size_t src_ = 0;
};

// Reads consecutive native-order T values from unaligned bytes as doubles: a
// random-access iterator, so vector::assign sizes the vector once and
// converts straight into it (no zero fill before the copy).
template <class T>
struct NativeReader {
  using iterator_category = std::random_access_iterator_tag;
  using value_type = double;
  using difference_type = std::ptrdiff_t;
  using pointer = const double*;
  using reference = double;
  const uint8_t* p;
  double operator*() const {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return static_cast<double>(v);
  }
  NativeReader& operator++() { return p += sizeof(T), *this; }
  NativeReader operator++(int) { return NativeReader{(p += sizeof(T)) - sizeof(T)}; }
  NativeReader& operator--() { return p -= sizeof(T), *this; }
  NativeReader& operator+=(difference_type d) { return p += d * difference_type(sizeof(T)), *this; }
  difference_type operator-(const NativeReader& o) const {
    return (p - o.p) / static_cast<difference_type>(sizeof(T));
  }
  bool operator==(const NativeReader& o) const { return p == o.p; }
  bool operator!=(const NativeReader& o) const { return p != o.p; }
};

// Numbers of a native-order dtype, loaded as T (memcpy: any alignment).
// C order: one converting pass into a vector sized once; Fortran order: each
// element read from its source position.
template <class T>
void loadTyped(const uint8_t* p, size_t count, SourceOrder& order, bool c_order,
               std::vector<double>* out) {
  if (c_order) {
    out->reserve(count);  // allocated, not yet touched: advise before the first write
    adviseHugePages(out->data(), count * sizeof(double));
    out->assign(NativeReader<T>{p}, NativeReader<T>{p + count * sizeof(T)});
    return;
  }
  out->resize(count);
  for (size_t i = 0; i < count; ++i) {
    T v;
    std::memcpy(&v, p + order.next() * sizeof(T), sizeof(T));
    (*out)[i] = static_cast<double>(v);
  }
}

// The common dtypes in the host's byte order without the per-element
// switch of loadNumber; false for the others (half floats, bools, 1- and
// 2-byte integers, the other byte order), which take loadNumber.
bool loadNative(const uint8_t* p, size_t count, const NumpyDtype& t, SourceOrder& order,
                bool c_order, std::vector<double>* out) {
  if (count == 0 || (t.big_endian && t.itemsize > 1) || hostIsBigEndian()) return false;
  const char k = t.kind;
  const size_t n = t.itemsize;
  if (k == 'f' && n == 8)
    loadTyped<double>(p, count, order, c_order, out);
  else if (k == 'f' && n == 4)
    loadTyped<float>(p, count, order, c_order, out);
  else if (k == 'i' && n == 8)
    loadTyped<int64_t>(p, count, order, c_order, out);
  else if (k == 'i' && n == 4)
    loadTyped<int32_t>(p, count, order, c_order, out);
  else if (k == 'u' && n == 8)
    loadTyped<uint64_t>(p, count, order, c_order, out);
  else if (k == 'u' && n == 4)
    loadTyped<uint32_t>(p, count, order, c_order, out);
  else
    return false;
  return true;
}

Status fillElements(const uint8_t* p, size_t count, const NumpyDtype& t, bool fortran, Array& a,
                    const std::string& ctx) {
  SourceOrder order(a.shape, fortran);
  const bool text = t.kind == 'S' || t.kind == 'U';
  const uint64_t per_element = text ? sizeof(std::string) + t.itemsize : sizeof(double);
  if (Status st = a.charge.add(
          count * per_element, ctx,
          "the array " + shapeString(a.shape) + (text ? " as strings" : " as doubles"));
      !st)
    return st;
  if (text) {
    a.strings.reserve(count);
    for (size_t i = 0; i < count; ++i) {
      Result<std::string> s = loadString(p + order.next() * t.itemsize, t, ctx);
      if (!s) return s.error();
      a.strings.push_back(std::move(*s));
    }
  } else {
    const bool c_order = !fortran || a.shape.size() <= 1;
    if (loadNative(p, count, t, order, c_order, &a.data)) return Status();
    a.data.resize(count);
    for (size_t i = 0; i < count; ++i) a.data[i] = loadNumber(p + order.next() * t.itemsize, t);
  }
  return Status();
}

}  // namespace

Result<NumpyDtype> parseNumpyDescr(const std::string& descr, const std::string& ctx) {
  if (descr.size() < 2 || std::string("<>|=").find(descr[0]) == std::string::npos)
    return makeError(ctx + ": unsupported dtype '" + printable(descr, 64) + "'");
  const char order = descr[0], kind = descr[1];
  if (kind == 'O')
    return makeError(ctx + ": object arrays ('" + printable(descr, 64) +
                     "') are not supported; save a numeric array");
  if (kind == 'V')
    return makeError(ctx + ": structured/void dtype '" + printable(descr, 64) +
                     "' is not supported");
  Result<size_t> n = descrItemCount(descr.substr(2), descr, ctx);
  if (!n) return n.error();
  if (!validItemSize(kind, *n))
    return makeError(ctx + ": unsupported dtype '" + printable(descr, 64) + "'");
  // 'U' counts characters of 4-byte UTF-32 code units; all others count bytes.
  NumpyDtype t{kind, kind == 'U' ? *n * 4 : *n, order == '>' || (order == '=' && hostIsBigEndian()),
               descr};
  if (order == '|' && t.itemsize > 1 && kind != 'S')
    return makeError(ctx + ": dtype '" + printable(descr, 64) + "' needs a byte order");
  return t;
}

Result<size_t> numpyByteCount(const NumpyDtype& t, const std::vector<int64_t>& shape,
                              const std::string& ctx) {
  if (t.itemsize == 0)
    return makeError(ctx + ": unsupported dtype '" + printable(t.descr, 64) + "'");
  const uint64_t limit = static_cast<uint64_t>(std::numeric_limits<int64_t>::max()) / t.itemsize;
  uint64_t nonzero = 1;
  bool empty = false;
  for (int64_t d : shape) {
    if (d < 0)
      return makeError(ctx + ": shape " + shapeString(shape) + " has a negative dimension");
    if (d == 0)
      empty = true;
    else if (static_cast<uint64_t>(d) > limit / nonzero)
      return makeError(ctx + ": shape " + shapeString(shape) + " is too large");
    else
      nonzero *= static_cast<uint64_t>(d);
  }
  if (nonzero > std::numeric_limits<size_t>::max() / t.itemsize)
    return makeError(ctx + ": shape " + shapeString(shape) + " is too large");
  return empty ? size_t{0} : static_cast<size_t>(nonzero) * t.itemsize;
}

Result<Array> decodeNumpyArray(const uint8_t* data, size_t size, const NumpyDtype& dtype,
                               const std::vector<int64_t>& shape, bool fortran_order,
                               const std::string& context) {
  Result<size_t> need = numpyByteCount(dtype, shape, context);
  if (!need) return need.error();
  if (*need != size)
    return makeError(context + ": array of dtype " + dtype.descr + " and shape " +
                     shapeString(shape) + " needs " + std::to_string(*need) +
                     " bytes, payload has " + std::to_string(size));
  Array a;
  a.shape = shape;
  a.dtype = dtype.descr;
  if (Status st = fillElements(data, *need / dtype.itemsize, dtype, fortran_order, a, context); !st)
    return st.error();
  return a;
}

}  // namespace smpl
