// numpy payloads inside pickles: raw element bytes in the dtype's byte order,
// C or Fortran order, widened to double in C order as core/array.h promises.
// The element decoding is core/numpy_dtype's, shared with the .npy reader;
// this file adds what only pickles need: the dtype comes from a numpy.dtype
// object rather than a descr string, and every allocation is charged to the
// pickle's byte budget first.
#include "core/io/numpy_dtype.h"
#include "core/io/pickle/pickle_internal.h"

namespace smpl {
namespace pickle {

std::string descrOf(const DtypeInfo& d) {
  int64_t n = d.kind == 'U' ? d.itemsize / 4 : d.itemsize;
  return std::string(1, d.endian) + d.kind + std::to_string(n);
}

Result<Array> decodeArray(Heap& heap, const DtypeInfo& d, const std::vector<int64_t>& shape,
                          bool fortran, const uint8_t* data, size_t size) {
  const std::string descr = descrOf(d);
  Result<NumpyDtype> t = parseNumpyDescr(descr, heap.context());
  if (!t) return t.error();
  // A 'U' item size that is not a whole number of UTF-32 characters.
  if (static_cast<int64_t>(t->itemsize) != d.itemsize)
    return heap.fail("unsupported dtype '" + descr + "'");
  Result<size_t> bytes = numpyByteCount(*t, shape, heap.context());
  if (!bytes) return bytes.error();
  // On a size mismatch decodeNumpyArray reports it before allocating anything.
  if (*bytes == size) {
    const uint64_t count = *bytes / t->itemsize;
    if (t->kind == 'U' || t->kind == 'S') {
      PK_TRY(heap.charge(count * (sizeof(std::string) + t->itemsize), "string array"));
    } else {
      PK_TRY(heap.charge(count * sizeof(double), "array"));
    }
  }
  return decodeNumpyArray(data, size, *t, shape, fortran, heap.context());
}

}  // namespace pickle
}  // namespace smpl
