// The allow-list of pickle globals and what REDUCE, NEWOBJ and BUILD do with
// each of them. Every allowed callable is reimplemented here for the argument
// forms model files use; anything else is refused by name.
#include <algorithm>
#include <cstring>

#include "core/io/pickle/pickle_internal.h"
#include "core/io/printable.h"

namespace smpl {
namespace pickle {

// ---- heap ------------------------------------------------------------------

uint64_t heapByteLimit(const PickleLimits& limits, uint64_t input_bytes) {
  const uint64_t scaled = input_bytes > UINT64_MAX / std::max<uint64_t>(limits.expansion, 1)
                              ? UINT64_MAX
                              : input_bytes * limits.expansion;
  return std::min(limits.max_total_bytes, std::max(limits.expansion_floor, scaled));
}

Heap::Heap(const std::string& context, const PickleLimits& limits, uint64_t input_bytes,
           VmOptions options)
    : context_(context),
      options_(std::move(options)),
      limit_(heapByteLimit(limits, input_bytes)),
      input_bytes_(input_bytes),
      expansion_(limits.expansion),
      expansion_floor_(limits.expansion_floor),
      input_bound_(limit_ < limits.max_total_bytes) {
  objs_.emplace_back();  // Ref 0: None
}

Status Heap::count(uint64_t bytes, const char* what) {
  if (bytes > limit_ || used_ > limit_ - bytes) return check(bytes, what);
  used_ += bytes;
  return Status::success();
}

Status Heap::check(uint64_t bytes, const char* what) const {
  if (bytes <= limit_ && used_ <= limit_ - bytes) return Status::success();
  if (!input_bound_)
    return fail(std::string(what) + " of " + std::to_string(bytes) +
                " bytes exceeds the limit of " + std::to_string(limit_) + " bytes for one pickle");
  return fail(std::string(what) + " of " + std::to_string(bytes) + " bytes exceeds the limit of " +
              std::to_string(limit_) + " bytes for an input of " + std::to_string(input_bytes_) +
              " bytes (" + std::to_string(expansion_) + " bytes per input byte, at least " +
              formatBytes(expansion_floor_) +
              "; beyond that only shared objects repeated many times could need more)");
}

Status Heap::charge(uint64_t bytes, const char* what) {
  if (bytes > limit_ || used_ > limit_ - bytes) return check(bytes, what);
  if (Status st = budget_.add(bytes, context_, std::string("unpickling (") + what + ")"); !st)
    return st;
  used_ += bytes;
  return Status::success();
}

Result<Ref> Heap::add(PyObj obj) {
  PK_TRY(charge(sizeof(PyObj), "object"));
  if (objs_.size() >= UINT32_MAX) return fail("too many objects");
  objs_.push_back(std::move(obj));
  return static_cast<Ref>(objs_.size() - 1);
}

std::string typeName(const Heap& heap, Ref r) {
  const PyObj& o = heap.at(r);
  switch (o.kind) {
    case Kind::None:
      return "None";
    case Kind::Bool:
      return "bool";
    case Kind::Int:
      return "int";
    case Kind::Float:
      return "float";
    case Kind::Str:
      return "str";
    case Kind::Bytes:
      return "bytes";
    case Kind::List:
      return "list";
    case Kind::Tuple:
      return "tuple";
    case Kind::Dict:
      return "dict";
    case Kind::Set:
      return "set";
    case Kind::NdArray:
      return "numpy.ndarray";
    case Kind::Dtype:
      return "numpy.dtype";
    case Kind::Global:
    case Kind::Instance:
      return o.text;
  }
  return "object";
}

bool stringValue(const Heap& heap, Ref r, std::string* out) {
  const PyObj& o = heap.at(r);
  if (o.kind != Kind::Str && o.kind != Kind::Bytes) return false;
  *out = std::string(o.bytes());
  return true;
}

bool dictGet(const Heap& heap, Ref dict, const std::string& key, Ref* out) {
  const PyObj& d = heap.at(dict);
  if (d.kind != Kind::Dict) return false;
  bool found = false;
  std::string k;
  for (size_t i = 0; i + 1 < d.items.size(); i += 2) {
    if (stringValue(heap, d.items[i], &k) && k == key) {
      *out = d.items[i + 1];
      found = true;
    }
  }
  return found;
}

// ---- the allow-list ----------------------------------------------------------

namespace {

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool inPackage(const std::string& module, const std::string& package) {
  return module == package || startsWith(module, package + ".");
}

// What tools' containers add (VmOptions::tree): joblib's array wrapper,
// defaultdict and its factory, numpy's ndarray subclasses.
bool resolveTreeGlobal(const std::string& module, const std::string& name, GlobalId* id) {
  const bool builtins = module == "builtins" || module == "__builtin__";
  if (module == "joblib.numpy_pickle" && name == "NumpyArrayWrapper")
    *id = GlobalId::JoblibWrapper;
  else if (module == "collections" && name == "defaultdict")
    *id = GlobalId::DefaultDict;
  else if (builtins && (name == "dict" || name == "list" || name == "set" || name == "int" ||
                        name == "float" || name == "str" || name == "tuple"))
    *id = GlobalId::Factory;
  else if (module == "numpy" && (name == "memmap" || name == "matrix"))
    *id = GlobalId::NdArrayClass;
  else
    return false;
  return true;
}

}  // namespace

Result<GlobalId> resolveGlobal(const Heap& heap, const std::string& module,
                               const std::string& name) {
  static const struct {
    const char* module;
    const char* name;
    GlobalId id;
  } kTable[] = {
      {"numpy.core.multiarray", "_reconstruct", GlobalId::Reconstruct},
      {"numpy._core.multiarray", "_reconstruct", GlobalId::Reconstruct},
      {"numpy", "ndarray", GlobalId::NdArrayClass},
      {"numpy", "dtype", GlobalId::DtypeClass},
      {"numpy.core.multiarray", "scalar", GlobalId::Scalar},
      {"numpy._core.multiarray", "scalar", GlobalId::Scalar},
      {"numpy.core.numeric", "_frombuffer", GlobalId::FromBuffer},
      {"numpy._core.numeric", "_frombuffer", GlobalId::FromBuffer},
      {"_codecs", "encode", GlobalId::CodecsEncode},
      {"copy_reg", "_reconstructor", GlobalId::Reconstructor},
      {"copyreg", "_reconstructor", GlobalId::Reconstructor},
      {"copy_reg", "__newobj__", GlobalId::NewObj},
      {"copyreg", "__newobj__", GlobalId::NewObj},
      {"builtins", "set", GlobalId::Set},
      {"__builtin__", "set", GlobalId::Set},
      {"builtins", "frozenset", GlobalId::FrozenSet},
      {"__builtin__", "frozenset", GlobalId::FrozenSet},
      {"builtins", "bytearray", GlobalId::ByteArray},
      {"__builtin__", "bytearray", GlobalId::ByteArray},
      {"builtins", "bytes", GlobalId::Bytes},  // protocols 0-2 write b'' as bytes()
      {"__builtin__", "bytes", GlobalId::Bytes},
      {"builtins", "object", GlobalId::Object},
      {"__builtin__", "object", GlobalId::Object},
      {"collections", "OrderedDict", GlobalId::OrderedDict},
  };
  for (const auto& e : kTable) {
    if (module == e.module && name == e.name) return e.id;
  }
  // chumpy: Ch and its many subclasses (ch_ops.add, Select, ...). Every one is
  // rebuilt as a plain state holder, so the exact class does not matter.
  if (inPackage(module, "chumpy")) return GlobalId::Ch;
  if (inPackage(module, "scipy.sparse")) {
    if (name == "csc_matrix" || name == "csc_array") return GlobalId::Csc;
    if (name == "csr_matrix" || name == "csr_array") return GlobalId::Csr;
    if (name == "coo_matrix" || name == "coo_array") return GlobalId::Coo;
  }
  const std::string full = printable(module + "." + name, 200);
  const VmOptions& options = heap.options();
  if (options.tree) {
    GlobalId id;
    if (resolveTreeGlobal(module, name, &id)) return id;
    if (inPackage(module, "joblib") && (name == "NDArrayWrapper" || name == "ZNDArrayWrapper"))
      return heap.fail("an array that joblib < 0.10 stored in a separate file ('" + full +
                       "'): load it with joblib and dump it again with joblib >= 0.10");
  }
  if (options.torch_storage) {
    GlobalId id;
    if (resolveTorchGlobal(module, name, &id)) return id;
  } else if (options.tree && inPackage(module, "torch")) {
    // A tensor pickled outside torch.save: its storage is _load_from_bytes
    // (pickle_torch_legacy.cpp).
    GlobalId id;
    if (module == "torch.storage" && name == "_load_from_bytes") {
      if (options.inside_load_from_bytes)
        return heap.fail(
            "torch.storage._load_from_bytes inside the bytes of another is not "
            "supported (torch never nests them)");
      return GlobalId::TorchLoadFromBytes;
    }
    if (resolveTorchGlobal(module, name, &id)) return id;
    return heap.fail("refusing pickle global '" + full +
                     "': of torch's objects only tensors are read (convert other objects' tensors "
                     "with .numpy() before pickling)");
  }
  return heap.fail("refusing pickle global '" + full + "' (not model data)");
}

// ---- REDUCE / NEWOBJ ---------------------------------------------------------

namespace {

Result<Ref> makeObj(Heap& heap, Kind kind, std::vector<Ref> items = {}, std::string text = {}) {
  PK_TRY(heap.charge(items.size() * sizeof(Ref) + text.size(), "object"));
  PyObj o;
  o.kind = kind;
  o.items = std::move(items);
  o.text = std::move(text);
  return heap.add(std::move(o));
}

Result<Ref> makeInstance(Heap& heap, GlobalId cls, const std::string& name, std::vector<Ref> args) {
  Result<Ref> r = makeObj(heap, Kind::Instance, std::move(args), name);
  if (r) heap.at(*r).global = cls;
  return r;
}

// str.encode('latin-1'): every code point must be below 256.
Result<Ref> encodeLatin1(Heap& heap, Ref text, Ref encoding) {
  std::string enc;
  if (heap.at(text).kind != Kind::Str || !stringValue(heap, encoding, &enc)) {
    return heap.fail("_codecs.encode needs (str, encoding)");
  }
  std::transform(enc.begin(), enc.end(), enc.begin(),
                 [](char c) { return c == '_' ? '-' : std::tolower(c); });
  if (enc != "latin1" && enc != "latin-1" && enc != "iso-8859-1" && enc != "iso8859-1") {
    return heap.fail("_codecs.encode with encoding '" + enc.substr(0, 40) + "' is not supported");
  }
  const std::string_view s = heap.at(text).bytes();
  std::string out(s.size(), '\0');  // the latin-1 bytes are never more than the UTF-8 ones
  const unsigned char* in = reinterpret_cast<const unsigned char*>(s.data());
  size_t w = 0;
  for (size_t k = 0; k < s.size();) {
    const unsigned char c = in[k];
    if (c < 0x80) {
      out[w++] = static_cast<char>(c);
      k += 1;
    } else if ((c & 0xE0) == 0xC0 && k + 1 < s.size() && c <= 0xC3 && (in[k + 1] & 0xC0) == 0x80) {
      out[w++] = static_cast<char>(((c & 0x03) << 6) | (in[k + 1] & 0x3F));
      k += 2;
    } else {
      return heap.fail("_codecs.encode: text is not latin-1");
    }
  }
  out.resize(w);
  return makeObj(heap, Kind::Bytes, {}, std::move(out));
}

// set(iterable), frozenset(iterable), OrderedDict(pairs): copy the items.
Result<Ref> fromIterable(Heap& heap, Kind kind, const std::vector<Ref>& args, const char* name) {
  if (args.empty()) return makeObj(heap, kind);
  const PyObj& src = heap.at(args[0]);
  bool iterable = src.kind == Kind::List || src.kind == Kind::Tuple || src.kind == Kind::Set;
  if (args.size() != 1 || !iterable)
    return heap.fail(std::string(name) + "() with these arguments is not supported");
  std::vector<Ref> items = src.items;
  if (kind != Kind::Dict) return makeObj(heap, kind, std::move(items));
  std::vector<Ref> pairs;
  for (Ref p : items) {
    const PyObj& pair = heap.at(p);
    if ((pair.kind != Kind::Tuple && pair.kind != Kind::List) || pair.items.size() != 2) {
      return heap.fail("OrderedDict() needs (key, value) pairs");
    }
    pairs.insert(pairs.end(), pair.items.begin(), pair.items.end());
  }
  return makeObj(heap, Kind::Dict, std::move(pairs));
}

Result<Ref> makeByteArray(Heap& heap, const std::vector<Ref>& args) {
  if (args.empty()) return makeObj(heap, Kind::Bytes);
  if (args.size() == 1 && heap.at(args[0]).kind == Kind::Bytes) {
    return makeObj(heap, Kind::Bytes, {}, std::string(heap.at(args[0]).bytes()));
  }
  if (args.size() == 2) return encodeLatin1(heap, args[0], args[1]);
  return heap.fail("bytearray() with these arguments is not supported");
}

}  // namespace

Result<Ref> newObject(Heap& heap, Ref cls, Ref args) {
  const PyObj& c = heap.at(cls);
  if (c.kind != Kind::Global)
    return heap.fail("NEWOBJ on a " + typeName(heap, cls) + " (not a class)");
  if (heap.at(args).kind != Kind::Tuple) return heap.fail("NEWOBJ arguments are not a tuple");
  GlobalId id = c.global;
  std::string name = c.text;
  switch (id) {
    case GlobalId::Ch:
    case GlobalId::Csc:
    case GlobalId::Csr:
    case GlobalId::Coo:
    case GlobalId::Object:
    case GlobalId::JoblibWrapper:
      return makeInstance(heap, id, name, heap.at(args).items);
    case GlobalId::OrderedDict:
      return makeObj(heap, Kind::Dict);
    case GlobalId::Set:
    case GlobalId::FrozenSet:
      return makeObj(heap, Kind::Set);
    case GlobalId::ByteArray:
      return makeObj(heap, Kind::Bytes);
    default:
      return heap.fail("cannot create a '" + name + "' object");
  }
}

namespace {

Result<Ref> reconstructArray(Heap& heap, const std::vector<Ref>& args) {
  if (args.size() != 3 || heap.at(args[0]).kind != Kind::Global ||
      heap.at(args[0]).global != GlobalId::NdArrayClass) {
    return heap.fail("_reconstruct supports only numpy.ndarray");
  }
  return makeObj(heap, Kind::NdArray);  // filled by BUILD
}

// numpy.dtype('f8', align, copy): the name gives kind and item size; BUILD
// then sets the byte order (and the item size of string dtypes).
Result<Ref> makeDtype(Heap& heap, const std::vector<Ref>& args) {
  std::string name;
  if (args.empty() || !stringValue(heap, args[0], &name))
    return heap.fail("numpy.dtype needs a type name");
  DtypeInfo d;
  size_t k = 0;
  if (!name.empty() && std::strchr("<>|=", name[0])) d.endian = name[k++];
  if (k >= name.size() || !std::isalpha(static_cast<unsigned char>(name[k]))) {
    return heap.fail("unsupported numpy dtype '" + name.substr(0, 40) + "'");
  }
  d.kind = name[k++];
  int64_t n = 0;
  for (; k < name.size(); ++k) {
    if (!std::isdigit(static_cast<unsigned char>(name[k])) || n > (int64_t(1) << 40)) {
      return heap.fail("unsupported numpy dtype '" + name.substr(0, 40) + "'");
    }
    n = n * 10 + (name[k] - '0');
  }
  d.itemsize = d.kind == 'U' ? 4 * n : n;
  if (name[0] != '<' && name[0] != '>') {
    bool one_byte =
        d.itemsize == 1 || d.kind == 'S' || d.kind == 'b' || d.kind == 'O' || d.kind == 'V';
    d.endian = one_byte ? '|' : '<';
  }
  if (d.endian == '=') d.endian = '<';
  Result<Ref> r = makeObj(heap, Kind::Dtype);
  if (r) heap.at(*r).dtype = d;
  return r;
}

}  // namespace

Result<std::vector<int64_t>> shapeOf(Heap& heap, Ref r) {
  const PyObj& t = heap.at(r);
  if (t.kind == Kind::Int) return std::vector<int64_t>{t.i};
  if (t.kind != Kind::Tuple && t.kind != Kind::List) return heap.fail("array shape is not a tuple");
  if (t.items.size() > 64) return heap.fail("array has more than 64 dimensions");
  std::vector<int64_t> shape;
  for (Ref d : t.items) {
    const PyObj& v = heap.at(d);
    if (v.kind != Kind::Int || v.i < 0) return heap.fail("array shape has a bad dimension");
    shape.push_back(v.i);
  }
  return shape;
}

namespace {

Result<Ref> arrayObject(Heap& heap, Result<Array> array) {
  if (!array) return array.error();
  Result<Ref> r = makeObj(heap, Kind::NdArray);
  if (r) heap.at(*r).array = std::make_unique<Array>(std::move(*array));
  return r;
}

// numpy.core.multiarray.scalar(dtype, payload): a numpy scalar, kept as a 0-d array.
Result<Ref> makeScalar(Heap& heap, const std::vector<Ref>& args) {
  if (args.size() != 2 || heap.at(args[0]).kind != Kind::Dtype)
    return heap.fail("scalar() needs (dtype, data)");
  DtypeInfo d = heap.at(args[0]).dtype;
  if (d.kind == 'O') return heap.fail("object scalars are not supported");
  if (heap.at(args[1]).kind != Kind::Bytes) return heap.fail("scalar() data is not bytes");
  const std::string_view raw = heap.at(args[1]).bytes();
  Result<Ref> r = arrayObject(
      heap,
      decodeArray(heap, d, {}, false, reinterpret_cast<const uint8_t*>(raw.data()), raw.size()));
  // An integer scalar's exact value, for a dict key (np.int64(2**53 + 1)):
  // the array's data is widened to double.
  if (r && (d.kind == 'i' || d.kind == 'u') && raw.size() == static_cast<size_t>(d.itemsize)) {
    std::string little(raw);
    if (d.endian == '>') std::reverse(little.begin(), little.end());
    heap.at(*r).exact =
        exactDecimal(reinterpret_cast<const uint8_t*>(little.data()), little.size(), d.kind == 'i');
  }
  return r;
}

// numpy.core.numeric._frombuffer(buffer, dtype, shape, order): protocol 5 arrays.
Result<Ref> fromBuffer(Heap& heap, const std::vector<Ref>& args) {
  std::string order;
  if (args.size() != 4 || heap.at(args[0]).kind != Kind::Bytes ||
      heap.at(args[1]).kind != Kind::Dtype || !stringValue(heap, args[3], &order)) {
    return heap.fail("_frombuffer needs (buffer, dtype, shape, order)");
  }
  Result<std::vector<int64_t>> shape = shapeOf(heap, args[2]);
  if (!shape) return shape.error();
  DtypeInfo d = heap.at(args[1]).dtype;
  const std::string_view raw = heap.at(args[0]).bytes();
  return arrayObject(heap, decodeArray(heap, d, *shape, order == "F",
                                       reinterpret_cast<const uint8_t*>(raw.data()), raw.size()));
}

}  // namespace

Result<Ref> callGlobal(Heap& heap, Ref callable, Ref args_ref) {
  const PyObj& c = heap.at(callable);
  if (c.kind != Kind::Global)
    return heap.fail("REDUCE on a " + typeName(heap, callable) + " (not callable)");
  if (heap.at(args_ref).kind != Kind::Tuple) return heap.fail("REDUCE arguments are not a tuple");
  GlobalId id = c.global;
  std::string name = c.text;
  std::vector<Ref> args = heap.at(args_ref).items;
  switch (id) {
    case GlobalId::Reconstruct:
      return reconstructArray(heap, args);
    case GlobalId::DtypeClass:
      return makeDtype(heap, args);
    case GlobalId::Scalar:
      return makeScalar(heap, args);
    case GlobalId::FromBuffer:
      return fromBuffer(heap, args);
    case GlobalId::CodecsEncode:
      if (args.size() != 2) return heap.fail("_codecs.encode needs (str, encoding)");
      return encodeLatin1(heap, args[0], args[1]);
    case GlobalId::Reconstructor: {
      if (args.size() != 3) return heap.fail("copyreg._reconstructor needs 3 arguments");
      Result<Ref> empty = makeObj(heap, Kind::Tuple);
      if (!empty) return empty;
      return newObject(heap, args[0], *empty);
    }
    case GlobalId::NewObj: {
      if (args.empty()) return heap.fail("copyreg.__newobj__ needs a class");
      Result<Ref> rest = makeObj(heap, Kind::Tuple, std::vector<Ref>(args.begin() + 1, args.end()));
      if (!rest) return rest;
      return newObject(heap, args[0], *rest);
    }
    case GlobalId::Set:
      return fromIterable(heap, Kind::Set, args, "set");
    case GlobalId::FrozenSet:
      return fromIterable(heap, Kind::Set, args, "frozenset");
    case GlobalId::OrderedDict:
      return fromIterable(heap, Kind::Dict, args, "OrderedDict");
    case GlobalId::ByteArray:
      return makeByteArray(heap, args);
    case GlobalId::Bytes:
      if (!args.empty()) return heap.fail("bytes() with arguments is not supported");
      return makeObj(heap, Kind::Bytes);
    case GlobalId::Ch:
    case GlobalId::Csc:
    case GlobalId::Csr:
    case GlobalId::Coo:
      return makeInstance(heap, id, name, std::move(args));
    case GlobalId::DefaultDict:  // defaultdict(factory): the items follow as SETITEMS
      return makeObj(heap, Kind::Dict);
    case GlobalId::TorchRebuildTensor:
    case GlobalId::TorchRebuildTensorV3:
    case GlobalId::TorchRebuildParameter:
    case GlobalId::TorchRebuildFromType:
    case GlobalId::TorchSize:
      return callTorchGlobal(heap, id, args);
    default:
      return heap.fail("calling '" + printable(name, 200) + "' is not supported");
  }
}

// ---- BUILD -------------------------------------------------------------------

namespace {

// Object arrays keep their elements (a list in the state) for parseObjectNpy;
// converting them to numbers happens only if a caller asks for them.
Status setObjectArrayState(Heap& heap, Ref obj, Ref shape_ref, const DtypeInfo& d, Ref raw_ref) {
  if (d.kind != 'O' || heap.at(raw_ref).kind != Kind::List)
    return heap.fail("ndarray state has list data for a non-object dtype");
  Result<std::vector<int64_t>> shape = shapeOf(heap, shape_ref);
  if (!shape) return shape.error();
  uint64_t count = 1;  // saturates at 2^40 (more elements than any list can hold)
  for (int64_t n : *shape)
    count = std::min<uint64_t>(count * std::min<uint64_t>(n, 1ull << 40), 1ull << 40);
  std::vector<Ref> items = heap.at(raw_ref).items;
  if (count != items.size())
    return heap.fail("object array of shape " + shapeString(*shape) + " holds " +
                     std::to_string(items.size()) + " elements");
  PyObj& o = heap.at(obj);
  o.object_array = true;
  o.object_shape = std::move(*shape);
  o.items = std::move(items);
  return Status::success();
}

// ndarray.__setstate__((version, shape, dtype, is_fortran, rawdata)); the
// version is missing in very old pickles.
Status setArrayState(Heap& heap, Ref obj, Ref state) {
  const PyObj& t = heap.at(state);
  if (t.kind != Kind::Tuple || (t.items.size() != 5 && t.items.size() != 4)) {
    return heap.fail("ndarray state is not a (version, shape, dtype, fortran, data) tuple");
  }
  size_t o = t.items.size() - 4;
  Ref shape_ref = t.items[o], dtype_ref = t.items[o + 1], fortran_ref = t.items[o + 2],
      raw_ref = t.items[o + 3];
  if (heap.at(dtype_ref).kind != Kind::Dtype) return heap.fail("ndarray state has no dtype");
  DtypeInfo d = heap.at(dtype_ref).dtype;
  const PyObj& raw = heap.at(raw_ref);
  if (d.kind == 'O' || raw.kind == Kind::List)
    return setObjectArrayState(heap, obj, shape_ref, d, raw_ref);
  if (raw.kind != Kind::Bytes)
    return heap.fail("ndarray data is a " + typeName(heap, raw_ref) + ", expected bytes");
  Result<std::vector<int64_t>> shape = shapeOf(heap, shape_ref);
  if (!shape) return shape.error();
  const PyObj& fortran = heap.at(fortran_ref);
  bool is_fortran = (fortran.kind == Kind::Bool || fortran.kind == Kind::Int) && fortran.i != 0;
  Result<Array> array =
      decodeArray(heap, d, *shape, is_fortran, reinterpret_cast<const uint8_t*>(raw.bytes().data()),
                  raw.bytes().size());
  if (!array) return array.error();
  heap.at(obj).array = std::make_unique<Array>(std::move(*array));
  return Status::success();
}

// dtype.__setstate__((version, endian, subarray, names, fields, elsize, alignment, flags[,
// metadata])).
Status setDtypeState(Heap& heap, Ref obj, Ref state) {
  const PyObj& t = heap.at(state);
  std::string endian;
  if (t.kind != Kind::Tuple || t.items.size() < 2 || !stringValue(heap, t.items[1], &endian) ||
      endian.size() != 1 || !std::strchr("<>|=", endian[0])) {
    return heap.fail("numpy dtype state is not supported");
  }
  if ((t.items.size() > 2 && heap.at(t.items[2]).kind != Kind::None) ||
      (t.items.size() > 3 && heap.at(t.items[3]).kind != Kind::None)) {
    return heap.fail("structured or sub-array dtypes are not supported");
  }
  DtypeInfo& d = heap.at(obj).dtype;
  d.endian = endian[0] == '=' ? '<' : endian[0];
  if (t.items.size() > 5 && std::strchr("USV", d.kind)) {
    const PyObj& elsize = heap.at(t.items[5]);
    if (elsize.kind == Kind::Int && elsize.i > 0) d.itemsize = elsize.i;
  }
  return Status::success();
}

}  // namespace

Status buildObject(Heap& heap, Ref obj, Ref state) {
  PyObj& o = heap.at(obj);
  switch (o.kind) {
    case Kind::NdArray:
      if (o.array || o.object_array) return heap.fail("BUILD on an ndarray that already has data");
      return setArrayState(heap, obj, state);
    case Kind::Dtype:
      return setDtypeState(heap, obj, state);
    case Kind::Instance: {
      // (dict_state, slot_state) from objects with __slots__: keep the dict.
      const PyObj& s = heap.at(state);
      if (s.kind == Kind::Tuple && s.items.size() == 2) {
        Ref first = s.items[0], second = s.items[1];
        state = heap.at(first).kind == Kind::Dict ? first : second;
      }
      heap.at(obj).state = state;
      return Status::success();
    }
    default:
      return heap.fail("BUILD on a " + typeName(heap, obj) + " is not supported");
  }
}

}  // namespace pickle
}  // namespace smpl
