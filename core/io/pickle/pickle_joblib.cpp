// joblib's arrays: joblib.dump pickles each numpy array as a
// joblib.numpy_pickle.NumpyArrayWrapper (NEWOBJ, then BUILD with the state
// {subclass, shape, order, dtype, allow_mmap[, numpy_array_alignment_bytes]})
// and writes the array itself right after the BUILD opcode, outside the
// pickle's opcodes (NumpyArrayWrapper.write_array in joblib/numpy_pickle.py,
// joblib 1.2; the same on GitHub joblib/joblib). NumpyUnpickler.load_build
// reads it back (read_array), and so does this file:
//   - joblib >= 1.2 with a seekable file stores numpy_array_alignment_bytes
//     (16): one byte giving a padding length, then that many padding bytes,
//     so the data starts aligned; joblib <= 1.1 (no such key) and unseekable
//     files (the key is None) write no padding;
//   - then the elements, in the array's `order` ('F': Fortran order);
//   - an array of dtype object is written with pickle.dump(array, protocol=2)
//     instead: a whole plain pickle, run here by the same data-only VM.
// The wrapper object becomes that ndarray in place, so memo references to it
// see the array.
#include "core/io/numpy_dtype.h"
#include "core/io/pickle/pickle_internal.h"

namespace smpl {
namespace pickle {
namespace {

struct WrapperState {
  DtypeInfo dtype;
  std::vector<int64_t> shape;
  bool fortran = false;
  bool padded = false;  // numpy_array_alignment_bytes is set: a padding byte comes first
};

Result<WrapperState> wrapperState(Heap& heap, Ref state) {
  if (heap.at(state).kind != Kind::Dict)
    return heap.fail("joblib NumpyArrayWrapper state is a " + typeName(heap, state) +
                     ", expected a dict");
  WrapperState w;
  Ref r;
  if (!dictGet(heap, state, "dtype", &r) || heap.at(r).kind != Kind::Dtype)
    return heap.fail("joblib NumpyArrayWrapper state has no numpy dtype");
  w.dtype = heap.at(r).dtype;
  if (!dictGet(heap, state, "shape", &r))
    return heap.fail("joblib NumpyArrayWrapper state has no shape");
  Result<std::vector<int64_t>> shape = shapeOf(heap, r);
  if (!shape) return shape.error();
  w.shape = std::move(*shape);
  std::string order = "C";
  if (dictGet(heap, state, "order", &r) &&
      (!stringValue(heap, r, &order) || (order != "C" && order != "F")))
    return heap.fail("joblib NumpyArrayWrapper order is not 'C' or 'F'");
  w.fortran = order == "F";
  if (dictGet(heap, state, "numpy_array_alignment_bytes", &r)) {
    const PyObj& a = heap.at(r);
    if (a.kind != Kind::None && a.kind != Kind::Int)
      return heap.fail("joblib NumpyArrayWrapper numpy_array_alignment_bytes is a " +
                       typeName(heap, r));
    w.padded = a.kind == Kind::Int;
  }
  return w;
}

// The inline pickle of an object array: its own PROTO ... STOP, own memo.
Status readObjectArray(Heap& heap, Ref wrapper, const WrapperState& w, const uint8_t* data,
                       size_t size, size_t* pos, const PickleLimits& limits) {
  heap.options().inside_joblib_object = true;
  size_t end = *pos;
  Result<Ref> array = runPickleAt(heap, data, size, *pos, limits, &end);
  heap.options().inside_joblib_object = false;
  if (!array) return array.error();
  const PyObj& a = heap.at(*array);
  if (a.kind != Kind::NdArray || (!a.object_array && !a.array))
    return heap.fail("joblib object array at byte " + std::to_string(*pos) + " holds a " +
                     typeName(heap, *array) + ", expected an ndarray");
  const std::vector<int64_t>& got = a.object_array ? a.object_shape : a.array->shape;
  if (got != w.shape)
    return heap.fail("joblib object array at byte " + std::to_string(*pos) + " has shape " +
                     shapeString(got) + "; its wrapper says " + shapeString(w.shape));
  *pos = end;
  PyObj moved = std::move(heap.at(*array));
  heap.at(*array) = PyObj();
  heap.at(wrapper) = std::move(moved);
  return Status::success();
}

}  // namespace

Status readJoblibArray(Heap& heap, Ref wrapper, const uint8_t* data, size_t size, size_t* pos,
                       const PickleLimits& limits) {
  if (heap.options().inside_joblib_object)
    return heap.fail("a joblib NumpyArrayWrapper inside an object array's pickle (byte " +
                     std::to_string(*pos) + ")");
  Result<WrapperState> w = wrapperState(heap, heap.at(wrapper).state);
  if (!w) return w.error();
  if (w->dtype.kind == 'O') return readObjectArray(heap, wrapper, *w, data, size, pos, limits);
  const size_t start = *pos;
  if (w->padded) {
    if (*pos >= size)
      return heap.fail("unexpected end of data at byte " + std::to_string(size) +
                       " (the padding byte of the joblib array after byte " +
                       std::to_string(start) + ")");
    const size_t padding = data[*pos];
    if (padding > size - *pos - 1)
      return heap.fail("joblib array padding of " + std::to_string(padding) + " bytes at byte " +
                       std::to_string(*pos) + " runs past the end");
    *pos += 1 + padding;
  }
  const std::string descr = descrOf(w->dtype);
  Result<NumpyDtype> t = parseNumpyDescr(descr, heap.context());
  if (!t) return t.error();
  Result<size_t> bytes = numpyByteCount(*t, w->shape, heap.context());
  if (!bytes) return bytes.error();
  if (*bytes > size - *pos)
    return heap.fail("joblib array " + shapeString(w->shape) + " of dtype '" + descr + "' needs " +
                     std::to_string(*bytes) + " bytes after byte " + std::to_string(*pos) + "; " +
                     std::to_string(size - *pos) + " are left");
  Result<Array> array = decodeArray(heap, w->dtype, w->shape, w->fortran, data + *pos, *bytes);
  if (!array) return array.error();
  *pos += *bytes;
  PyObj& o = heap.at(wrapper);
  o.kind = Kind::NdArray;
  o.global = GlobalId::Object;
  o.text.clear();
  o.items.clear();
  o.state = 0;
  o.array = std::make_unique<Array>(std::move(*array));
  return Status::success();
}

}  // namespace pickle
}  // namespace smpl
