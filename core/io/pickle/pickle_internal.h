// Private to the pickle reader (pickle_vm.cpp, pickle_objects.cpp,
// pickle.cpp). The unpickler's objects live in one arena (Heap) and refer to
// each other by index, so reference cycles built with the memo (a list that
// contains itself) cannot leak and nothing is freed twice: the whole graph is
// released at once when the Heap goes away.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/array.h"
#include "core/io/pickle/pickle.h"
#include "core/memory_budget.h"
#include "core/result.h"

#define PK_TRY(expr)                                 \
  do {                                               \
    ::smpl::Status pk_status_ = (expr);              \
    if (!pk_status_.ok()) return pk_status_.error(); \
  } while (0)

namespace smpl {
namespace pickle {

using Ref = uint32_t;

enum class Kind : uint8_t {
  None,
  Bool,
  Int,
  Float,
  Str,
  Bytes,
  List,
  Tuple,
  Dict,
  Set,
  Global,    // an allowed class or function (see GlobalId)
  NdArray,   // numpy array or scalar; `array` set once its data is known
  Dtype,     // numpy.dtype
  Instance,  // object of an allowed class (chumpy Ch, scipy sparse); `state` from BUILD
};

// The only globals a pickle may name. Each is rebuilt by our own code.
enum class GlobalId : uint8_t {
  Reconstruct,
  NdArrayClass,
  DtypeClass,
  Scalar,
  FromBuffer,
  CodecsEncode,
  Reconstructor,
  NewObj,
  Set,
  FrozenSet,
  ByteArray,
  Bytes,
  Object,
  OrderedDict,
  Ch,
  Csc,
  Csr,
  Coo,
};

struct DtypeInfo {
  char endian = '|';  // '<', '>', '|' (byte order irrelevant)
  char kind = 'f';    // numpy kind: f i u b U S O V c M m
  int64_t itemsize = 0;
};

struct PyObj {
  Kind kind = Kind::None;
  GlobalId global = GlobalId::Object;  // Global: which one; Instance: its class
  int64_t i = 0;                       // Int, Bool
  double f = 0;                        // Float
  std::string text;                    // Str (UTF-8), Bytes, Global/Instance name "module.name"
  // A large Bytes payload (py2 str, bytes opcodes) is not copied into `text`:
  // `view` points into the pickle's own bytes, which outlive the Heap.
  // Read Str/Bytes contents through bytes(), never `text` directly.
  const char* view = nullptr;
  size_t view_size = 0;
  std::string_view bytes() const {
    return view ? std::string_view(view, view_size) : std::string_view(text);
  }
  std::vector<Ref> items;        // List/Tuple/Set; Dict as key,value,key,value; Instance ctor args
  Ref state = 0;                 // Instance: BUILD state (0 = none; 0 is always the None object)
  DtypeInfo dtype;               // Dtype
  std::unique_ptr<Array> array;  // NdArray
  bool object_array = false;  // NdArray of dtype 'O': elements in `items`, shape in `object_shape`
  std::vector<int64_t> object_shape;
};

// Arena of objects. Index 0 is a shared None. Every allocation is charged to
// a byte budget (PickleLimits::max_total_bytes) before it happens.
class Heap {
 public:
  Heap(const std::string& context, uint64_t byte_limit);
  PyObj& at(Ref r) { return objs_[r]; }
  const PyObj& at(Ref r) const { return objs_[r]; }
  Result<Ref> add(PyObj obj);
  Status charge(uint64_t bytes, const char* what);
  const std::string& context() const { return context_; }
  Error fail(const std::string& message) const { return makeError(context_ + ": " + message); }

 private:
  std::deque<PyObj> objs_;  // deque: references stay valid while objects are added
  std::string context_;
  uint64_t used_ = 0;
  uint64_t limit_;
  MemoryCharge budget_;  // the same bytes, against the run's memory budget
};

// Name of an object's type for errors ("list", "numpy.ndarray", ...).
std::string typeName(const Heap& heap, Ref r);

// True for Str or Bytes; `out` gets the raw text.
bool stringValue(const Heap& heap, Ref r, std::string* out);

// Look up a string key in a Dict object; returns false if absent (last match wins).
bool dictGet(const Heap& heap, Ref dict, const std::string& key, Ref* out);

// Resolve "module" + "name" to an allowed global, or refuse it by name.
Result<GlobalId> resolveGlobal(const Heap& heap, const std::string& module,
                               const std::string& name);

// REDUCE: call an allowed global with a tuple of arguments.
Result<Ref> callGlobal(Heap& heap, Ref callable, Ref args);
// NEWOBJ / copyreg.__newobj__ / copyreg._reconstructor: cls.__new__(cls, *args).
Result<Ref> newObject(Heap& heap, Ref cls, Ref args);
// BUILD: apply `state` to `obj` (ndarray, dtype, Ch, sparse matrix).
Status buildObject(Heap& heap, Ref obj, Ref state);

// Decode a raw numpy payload into an Array (C order, values widened to double).
Result<Array> decodeArray(Heap& heap, const DtypeInfo& dtype, const std::vector<int64_t>& shape,
                          bool fortran, const uint8_t* data, size_t size);
// "<f8", "|b1", "<U6": the descr numpy prints for a dtype.
std::string descrOf(const DtypeInfo& dtype);

// Run the VM over a whole pickle; returns the object STOP left.
Result<Ref> runPickle(Heap& heap, const uint8_t* data, size_t size, const PickleLimits& limits);

// Turn an unpickled value into an Array if it is array-like; false if it is
// not (None, dicts, other objects are dropped by the caller). Errors only for
// malformed data (bad sparse indices) or limits.
Result<bool> toArray(Heap& heap, Ref r, Array* out);

}  // namespace pickle
}  // namespace smpl
