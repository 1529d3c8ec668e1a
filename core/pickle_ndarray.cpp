// numpy payloads inside pickles: raw element bytes in the dtype's byte order,
// C or Fortran order, widened to double in C order as core/array.h promises.
#include <cmath>
#include <cstring>

#include "core/pickle_internal.h"

namespace smpl {
namespace pickle {

std::string descrOf(const DtypeInfo& d) {
  int64_t n = d.kind == 'U' ? d.itemsize / 4 : d.itemsize;
  return std::string(1, d.endian) + d.kind + std::to_string(n);
}

namespace {

uint64_t loadUint(const uint8_t* p, int64_t size, bool big_endian) {
  uint64_t v = 0;
  for (int64_t k = 0; k < size; ++k) v = (v << 8) | p[big_endian ? k : size - 1 - k];
  return v;
}

double halfToDouble(uint16_t h) {
  int exponent = (h >> 10) & 0x1F;
  int mantissa = h & 0x3FF;
  double v;
  if (exponent == 0) {
    v = std::ldexp(mantissa, -24);
  } else if (exponent == 31) {
    v = mantissa ? NAN : INFINITY;
  } else {
    v = std::ldexp(mantissa + 1024, exponent - 25);
  }
  return (h & 0x8000) ? -v : v;
}

double numberAt(const uint8_t* p, const DtypeInfo& d) {
  uint64_t bits = loadUint(p, d.itemsize, d.endian == '>');
  switch (d.kind) {
    case 'b': return bits != 0 ? 1.0 : 0.0;
    case 'u': return static_cast<double>(bits);
    case 'i': {
      int shift = 64 - 8 * static_cast<int>(d.itemsize);
      return static_cast<double>(static_cast<int64_t>(bits << shift) >> shift);
    }
    default: break;  // 'f'
  }
  if (d.itemsize == 2) return halfToDouble(static_cast<uint16_t>(bits));
  if (d.itemsize == 4) {
    uint32_t b32 = static_cast<uint32_t>(bits);
    float f;
    std::memcpy(&f, &b32, 4);
    return f;
  }
  double v;
  std::memcpy(&v, &bits, 8);
  return v;
}

std::string stringAt(const uint8_t* p, const DtypeInfo& d) {
  std::string s;
  if (d.kind == 'S') {
    int64_t n = d.itemsize;
    while (n > 0 && p[n - 1] == 0) --n;  // numpy strips trailing NULs
    return std::string(reinterpret_cast<const char*>(p), n);
  }
  int64_t count = d.itemsize / 4;
  while (count > 0 && loadUint(p + 4 * (count - 1), 4, d.endian == '>') == 0) --count;
  for (int64_t k = 0; k < count; ++k) {
    uint32_t cp = static_cast<uint32_t>(loadUint(p + 4 * k, 4, d.endian == '>'));
    appendUtf8(&s, cp > 0x10FFFF ? 0xFFFD : cp);
  }
  return s;
}

bool supported(const DtypeInfo& d) {
  switch (d.kind) {
    case 'f': return d.itemsize == 2 || d.itemsize == 4 || d.itemsize == 8;
    case 'i': case 'u': return d.itemsize == 1 || d.itemsize == 2 || d.itemsize == 4 || d.itemsize == 8;
    case 'b': return d.itemsize == 1;
    case 'S': return d.itemsize >= 0;
    case 'U': return d.itemsize >= 0 && d.itemsize % 4 == 0;
    default: return false;
  }
}

// Element count of `shape`, or -1 if it does not fit comfortably in 63 bits.
int64_t elementCount(const std::vector<int64_t>& shape) {
  int64_t n = 1;
  for (int64_t d : shape) {
    if (d < 0) return -1;
    if (d != 0 && n > (int64_t(1) << 62) / d) return -1;
    n *= d;
  }
  return n;
}

// Position in the payload of the element with C-order index `c`.
class SourceOrder {
 public:
  SourceOrder(const std::vector<int64_t>& shape, bool fortran) : shape_(shape), index_(shape.size(), 0) {
    fortran_ = fortran && shape.size() > 1;
    int64_t s = 1;
    strides_.resize(shape.size());
    for (size_t k = 0; k < shape.size(); ++k) {  // Fortran: first axis fastest
      strides_[k] = s;
      s *= shape[k];
    }
  }
  // Source offset of the current element; then step to the next in C order.
  int64_t next(int64_t c) {
    if (!fortran_) return c;
    int64_t src = 0;
    for (size_t k = 0; k < index_.size(); ++k) src += index_[k] * strides_[k];
    for (size_t k = index_.size(); k-- > 0;) {
      if (++index_[k] < shape_[k]) break;
      index_[k] = 0;
    }
    return src;
  }

 private:
  std::vector<int64_t> shape_, index_, strides_;
  bool fortran_ = false;
};

}  // namespace

Result<Array> decodeArray(Heap& heap, const DtypeInfo& d, const std::vector<int64_t>& shape, bool fortran,
                          const uint8_t* data, size_t size) {
  if (!supported(d)) return heap.fail("numpy dtype '" + descrOf(d) + "' is not supported");
  int64_t count = elementCount(shape);
  if (count < 0) return heap.fail("array shape " + shapeString(shape) + " is too large");
  if (d.itemsize > 0 && count > INT64_MAX / d.itemsize) {
    return heap.fail("array shape " + shapeString(shape) + " is too large");
  }
  uint64_t expected = static_cast<uint64_t>(count) * static_cast<uint64_t>(d.itemsize);
  if (expected != size) {
    return heap.fail("array of dtype " + descrOf(d) + " and shape " + shapeString(shape) + " needs " +
                     std::to_string(expected) + " bytes, payload has " + std::to_string(size));
  }
  Array a;
  a.shape = shape;
  a.dtype = descrOf(d);
  SourceOrder order(shape, fortran);
  if (d.kind == 'U' || d.kind == 'S') {
    PK_TRY(heap.charge(static_cast<uint64_t>(count) * (sizeof(std::string) + d.itemsize), "string array"));
    a.strings.reserve(count);
    for (int64_t c = 0; c < count; ++c) a.strings.push_back(stringAt(data + order.next(c) * d.itemsize, d));
    return a;
  }
  PK_TRY(heap.charge(static_cast<uint64_t>(count) * sizeof(double), "array"));
  a.data.resize(count);
  for (int64_t c = 0; c < count; ++c) a.data[c] = numberAt(data + order.next(c) * d.itemsize, d);
  return a;
}

}  // namespace pickle
}  // namespace smpl
