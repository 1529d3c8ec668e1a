// Private to the pickle reader (pickle_vm.cpp, pickle_objects.cpp,
// pickle.cpp). The unpickler's objects live in one arena (Heap) and refer to
// each other by index, so reference cycles built with the memo (a list that
// contains itself) cannot leak and nothing is freed twice: the whole graph is
// released at once when the Heap goes away.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/array.h"
#include "core/data_node.h"
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
  // Only for the readers of tools' containers (VmOptions::tree):
  JoblibWrapper,  // joblib.numpy_pickle.NumpyArrayWrapper: the array's bytes follow its BUILD
  DefaultDict,    // collections.defaultdict(factory): a dict
  Factory,        // builtins.dict / list / ...: only as a defaultdict's factory, never called
  // Only inside a torch .pt archive (VmOptions::torch_storage):
  TorchRebuildTensor,     // torch._utils._rebuild_tensor_v2 / _rebuild_tensor
  TorchRebuildTensorV3,   // torch._utils._rebuild_tensor_v3 (untyped storage + dtype)
  TorchRebuildParameter,  // torch._utils._rebuild_parameter(_with_state): its data
  TorchRebuildFromType,   // torch._tensor._rebuild_from_type_v2(func, type, args, state)
  TorchStorageType,       // torch.FloatStorage, torch.UntypedStorage, ... (a persistent id's type)
  TorchDtype,             // torch.float32, ... (_rebuild_tensor_v3's dtype)
  TorchTensorClass,       // torch.Tensor, torch.nn.parameter.Parameter (a type, never called)
  TorchSize,              // torch.Size(tuple): the tuple
  TorchStorage,           // Instance: a storage's bytes (view), element dtype, numel (i)
  // Only in tree mode outside a .pt archive (pickle_torch_legacy.cpp):
  TorchLoadFromBytes,  // torch.storage._load_from_bytes(b): one storage in torch's legacy format
};

struct DtypeInfo {
  char endian = '|';  // '<', '>', '|' (byte order irrelevant)
  char kind = 'f';    // numpy kind: f i u b U S O V c M m; 'B': bfloat16 (torch storages only)
  int64_t itemsize = 0;
};

// A torch storage's bytes, found by its key in the archive (core/io/pickle/torch_zip.cpp).
struct StorageBytes {
  const uint8_t* data = nullptr;
  size_t size = 0;
};

// What the VM rebuilds beyond model files. parsePickle leaves both off, so a
// model file meets exactly the allow-list it always met.
struct VmOptions {
  // Tools' containers (pickle_tree.h): joblib's NumpyArrayWrapper (the array's
  // bytes follow its BUILD opcode), collections.defaultdict, numpy.memmap.
  bool tree = false;
  // A torch .pt archive: BINPERSID ids ('storage', type, key, location, numel)
  // are looked up here, and torch's tensor rebuild functions are allowed.
  // `nbytes` is what the id declares (numel x element size): the record may
  // not be shorter, and a compressed one is not inflated past it.
  std::function<Result<StorageBytes>(const std::string& key, uint64_t nbytes)> torch_storage;
  bool torch_big_endian = false;  // the archive's `byteorder` record says "big"
  // Set while the inline pickle of a joblib object array runs: joblib writes
  // it with plain pickle.dump, so no NumpyArrayWrapper can occur inside.
  bool inside_joblib_object = false;
  // Set while the bytes of torch.storage._load_from_bytes are read
  // (pickle_torch_legacy.cpp): BINPERSID ids ('storage', type, key, location,
  // numel, view_metadata) add their storage here, its bytes bound once the
  // data after the pickles is reached.
  std::vector<Ref>* legacy_storages = nullptr;
  // Set while any pickle inside those bytes runs: a nested _load_from_bytes is refused.
  bool inside_load_from_bytes = false;
};

struct PyObj {
  Kind kind = Kind::None;
  GlobalId global = GlobalId::Object;  // Global: which one; Instance: its class
  int64_t i = 0;                       // Int, Bool
  double f = 0;                        // Float
  // An integer's exact decimal text where `i` cannot hold it: a Python int
  // beyond int64 (kept as a Float, `f` its approximation) or a numpy integer
  // scalar (an NdArray, whose data is widened to double). Dict keys use it:
  // a track id 2^53 + 1 must not become 2^53.
  std::string exact;
  std::string text;  // Str (UTF-8), Bytes, Global/Instance name "module.name"
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
// a byte budget before it happens: heapByteLimit(limits, input size), i.e.
// PickleLimits::max_total_bytes, or less for a small input (see PickleLimits).
class Heap {
 public:
  Heap(const std::string& context, const PickleLimits& limits, uint64_t input_bytes,
       VmOptions options = VmOptions());
  PyObj& at(Ref r) { return objs_[r]; }
  const PyObj& at(Ref r) const { return objs_[r]; }
  Result<Ref> add(PyObj obj);
  size_t size() const { return objs_.size(); }  // objects are Refs 0 .. size() - 1
  // Checks `bytes` against this pickle's limit and the run's memory budget, and holds both.
  Status charge(uint64_t bytes, const char* what);
  // Checks and counts `bytes` against this pickle's limit only: for memory that
  // outlives the heap and holds its own budget charge (a DataNode's arrays).
  Status count(uint64_t bytes, const char* what);
  // Whether count(bytes) would succeed, without counting: before a scratch
  // buffer whose result is then charged.
  Status check(uint64_t bytes, const char* what) const;
  const std::string& context() const { return context_; }
  const VmOptions& options() const { return options_; }
  VmOptions& options() { return options_; }
  Error fail(const std::string& message) const { return makeError(context_ + ": " + message); }

 private:
  std::deque<PyObj> objs_;  // deque: references stay valid while objects are added
  std::string context_;
  VmOptions options_;
  uint64_t used_ = 0;
  uint64_t limit_;
  uint64_t input_bytes_;
  uint64_t expansion_, expansion_floor_;
  bool input_bound_;     // limit_ comes from the input's size, not max_total_bytes
  MemoryCharge budget_;  // the same bytes, against the run's memory budget
};

// min(max_total_bytes, max(expansion_floor, expansion x input_bytes)).
uint64_t heapByteLimit(const PickleLimits& limits, uint64_t input_bytes);

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

// An ndarray shape from a pickled int or tuple of ints (>= 0, at most 64 of them).
Result<std::vector<int64_t>> shapeOf(Heap& heap, Ref r);

// Decode a raw numpy payload into an Array (C order, values widened to double).
Result<Array> decodeArray(Heap& heap, const DtypeInfo& dtype, const std::vector<int64_t>& shape,
                          bool fortran, const uint8_t* data, size_t size);
// "<f8", "|b1", "<U6": the descr numpy prints for a dtype.
std::string descrOf(const DtypeInfo& dtype);

// Little-endian two's complement bytes (LONG1/LONG4, a numpy integer's
// payload when `is_signed`) as exact decimal text ("-12",
// "9223372036854775808"); beyond kMaxExactIntBytes as hex ("0x1f...",
// "-0x..."): decimal conversion is quadratic in the length, hex is linear
// and still exact.
inline constexpr size_t kMaxExactIntBytes = 128;
std::string exactDecimal(const uint8_t* bytes, size_t n, bool is_signed);

// Run the VM over a whole pickle; returns the object STOP left.
Result<Ref> runPickle(Heap& heap, const uint8_t* data, size_t size, const PickleLimits& limits);
// The same from byte `start` of `data` (a pickle embedded in a stream, as joblib
// writes object arrays); `*end` gets the position after its STOP. Own stack and memo.
Result<Ref> runPickleAt(Heap& heap, const uint8_t* data, size_t size, size_t start,
                        const PickleLimits& limits, size_t* end);

// joblib (pickle_joblib.cpp): after BUILD on a NumpyArrayWrapper at `*pos`,
// read the array that follows and turn the wrapper into that ndarray in place.
Status readJoblibArray(Heap& heap, Ref wrapper, const uint8_t* data, size_t size, size_t* pos,
                       const PickleLimits& limits);

// torch (pickle_torch.cpp): BINPERSID's ('storage', type, key, location, numel)
// -> a TorchStorage object viewing the archive's bytes.
Result<Ref> persistentLoad(Heap& heap, Ref pid);
// The same for the object pickle inside torch.storage._load_from_bytes's
// bytes: ('storage', type, key, location, numel, view_metadata) -> a
// TorchStorage of `numel` elements whose bytes (view) are still unset; it is
// added to VmOptions::legacy_storages.
Result<Ref> legacyPersistentLoad(Heap& heap, Ref pid);
// torch.storage._load_from_bytes(b) (pickle_torch_legacy.cpp): the storage
// that torch's legacy serialization in `b` holds, viewing b's bytes.
Result<Ref> loadFromBytes(Heap& heap, Ref args, const PickleLimits& limits);
// REDUCE of the torch globals (TorchRebuildTensor ... TorchSize).
Result<Ref> callTorchGlobal(Heap& heap, GlobalId id, const std::vector<Ref>& args);
// Resolution of torch.* globals inside a .pt (nullopt-like: false when not a torch name).
bool resolveTorchGlobal(const std::string& module, const std::string& name, GlobalId* id);

// Turn any unpickled value into a DataNode (pickle_tree.cpp): dicts, lists,
// array leaves, None for what is not data. Errors for malformed data, limits,
// and nesting deeper than 32 levels; a cycle ends in None.
Result<DataNode> toTree(Heap& heap, Ref root);

// Turn an unpickled value into an Array if it is array-like; false if it is
// not (None, dicts, other objects are dropped by the caller). Errors only for
// malformed data (bad sparse indices) or limits.
Result<bool> toArray(Heap& heap, Ref r, Array* out);

}  // namespace pickle
}  // namespace smpl
