// torch tensors inside a .pt archive's data.pkl, rebuilt as arrays. What
// torch.save writes (torch/serialization.py and torch/_utils.py, torch 1.13;
// the same layout in torch 2.x on GitHub pytorch/pytorch):
//   BINPERSID ('storage', <type>, key, location, numel): a storage whose bytes
//     are the archive record data/<key>; <type> is a legacy class such as
//     torch.FloatStorage (numel elements of that type) or torch.UntypedStorage
//     (numel bytes). torch's find_class maps any name containing "Storage"
//     to its dtype, whatever the module; so does resolveTorchGlobal.
//   torch._utils._rebuild_tensor_v2(storage, storage_offset, size, stride,
//     requires_grad, backward_hooks[, metadata]) (and the older
//     _rebuild_tensor(storage, offset, size, stride)): element (i_0, i_1, ...)
//     of the tensor is storage element offset + sum_k i_k * stride_k;
//   _rebuild_tensor_v3(untyped storage, offset, size, stride, requires_grad,
//     hooks, dtype[, metadata]) (torch 2.x, dtypes without a legacy class):
//     the same, counted in elements of `dtype` over the storage's bytes;
//   _rebuild_parameter(data, requires_grad, hooks) (nn.Parameter) and
//     torch._tensor._rebuild_from_type_v2(func, type, args, state) (tensors
//     with Python attributes): the tensor that func(*args) rebuilds.
// In a plain pickle (np.save of a dict of tensors, pickle.dump) the storage
// is torch.storage._load_from_bytes(b) instead: pickle_torch_legacy.cpp.
// metadata {'neg': True} marks a negated view (torch._neg_view); 'conj'
// concerns complex tensors only, which are refused. Every index is checked
// against the storage's size before anything is read; the tensor's doubles
// are charged first.
#include <cstring>

#include "core/io/pickle/pickle_internal.h"
#include "core/io/printable.h"

namespace smpl {
namespace pickle {
namespace {

// The element type of a legacy storage class or a torch dtype name.
bool elementOf(const std::string& name, DtypeInfo* d) {
  static const struct {
    const char* storage;
    const char* dtype;
    const char* alias;
    char kind;
    int size;
  } kTypes[] = {
      {"DoubleStorage", "float64", "double", 'f', 8},
      {"FloatStorage", "float32", "float", 'f', 4},
      {"HalfStorage", "float16", "half", 'f', 2},
      {"BFloat16Storage", "bfloat16", "", 'B', 2},
      {"LongStorage", "int64", "long", 'i', 8},
      {"IntStorage", "int32", "int", 'i', 4},
      {"ShortStorage", "int16", "short", 'i', 2},
      {"CharStorage", "int8", "", 'i', 1},
      {"ByteStorage", "uint8", "", 'u', 1},
      {"BoolStorage", "bool", "", 'b', 1},
      {"UntypedStorage", "", "", 'u', 1},
      {"_UntypedStorage", "", "", 'u', 1},
      {"", "uint16", "", 'u', 2},
      {"", "uint32", "", 'u', 4},
      {"", "uint64", "", 'u', 8},
  };
  const std::string last = name.substr(name.rfind('.') + 1);
  for (const auto& t : kTypes) {
    if (last != t.storage && last != t.dtype && (!*t.alias || last != t.alias)) continue;
    d->kind = t.kind;
    d->itemsize = t.size;
    d->endian = t.size == 1 ? '|' : '<';
    return true;
  }
  return false;
}

bool intOf(const PyObj& o, int64_t* v) {
  if (o.kind != Kind::Int && o.kind != Kind::Bool) return false;
  *v = o.i;
  return true;
}

// Largest storage element a tensor reads, or false on overflow.
bool lastElement(const std::vector<int64_t>& size, const std::vector<int64_t>& stride,
                 int64_t offset, uint64_t* last) {
  constexpr uint64_t kCap = 1ull << 62;
  uint64_t at = static_cast<uint64_t>(offset);
  for (size_t k = 0; k < size.size(); ++k) {
    const uint64_t n = static_cast<uint64_t>(size[k]) - 1, s = static_cast<uint64_t>(stride[k]);
    if (s != 0 && n > (kCap - at) / s) return false;
    at += n * s;
  }
  *last = at;
  return true;
}

// The tensor's elements in C order, as contiguous bytes of `d` (bfloat16
// widened to little-endian float32, which `*d` then describes).
void gather(const uint8_t* storage, DtypeInfo* d, bool big_endian, const std::vector<int64_t>& size,
            const std::vector<int64_t>& stride, int64_t offset, uint64_t count,
            std::vector<uint8_t>* out) {
  const bool bf16 = d->kind == 'B';
  const size_t in = static_cast<size_t>(d->itemsize), width = bf16 ? 4 : in;
  out->resize(count * width);
  std::vector<int64_t> index(size.size(), 0);
  uint64_t at = static_cast<uint64_t>(offset);
  for (uint64_t e = 0; e < count; ++e) {
    const uint8_t* p = storage + at * in;
    uint8_t* q = out->data() + e * width;
    if (bf16) {  // the high half of a float32
      const uint16_t bits = big_endian ? static_cast<uint16_t>(p[0] << 8 | p[1])
                                       : static_cast<uint16_t>(p[1] << 8 | p[0]);
      const uint32_t f = static_cast<uint32_t>(bits) << 16;
      for (int b = 0; b < 4; ++b) q[b] = static_cast<uint8_t>(f >> (8 * b));
    } else {
      std::memcpy(q, p, in);
    }
    for (size_t k = size.size(); k-- > 0;) {  // odometer over the multi-index
      at += static_cast<uint64_t>(stride[k]);
      if (++index[k] < size[k]) break;
      at -= static_cast<uint64_t>(stride[k]) * static_cast<uint64_t>(size[k]);
      index[k] = 0;
    }
  }
  if (bf16) *d = DtypeInfo{'<', 'f', 4};
}

bool isCContiguous(const std::vector<int64_t>& size, const std::vector<int64_t>& stride) {
  int64_t expected = 1;
  for (size_t k = size.size(); k-- > 0;) {
    if (size[k] != 1 && stride[k] != expected) return false;
    expected *= size[k];
  }
  return true;
}

struct TensorArgs {
  Ref storage = 0, offset = 0, size = 0, stride = 0, metadata = 0;
  DtypeInfo element;
};

// The tensor of `t` as an ndarray object.
Result<Ref> rebuildTensor(Heap& heap, const TensorArgs& t) {
  const PyObj& s = heap.at(t.storage);
  const std::string key =
      s.items.empty() ? "" : printable(std::string(heap.at(s.items[0]).bytes()));
  int64_t offset = 0;
  if (!intOf(heap.at(t.offset), &offset) || offset < 0)
    return heap.fail("torch tensor of storage '" + key + "' has a bad storage offset");
  Result<std::vector<int64_t>> size = shapeOf(heap, t.size);
  if (!size) return size.error();
  Result<std::vector<int64_t>> stride = shapeOf(heap, t.stride);
  if (!stride) return stride.error();
  if (stride->size() != size->size())
    return heap.fail("torch tensor of storage '" + key + "' has size " + shapeString(*size) +
                     " but stride " + shapeString(*stride));
  DtypeInfo d = t.element;
  const uint64_t elements = s.view_size / static_cast<uint64_t>(d.itemsize);
  constexpr uint64_t kMaxElements = 1ull << 50;
  uint64_t count = 1, last = 0;
  for (int64_t n : *size) {
    if (n != 0 && count > kMaxElements / static_cast<uint64_t>(n))
      return heap.fail("torch tensor of size " + shapeString(*size) + " is too large");
    count *= static_cast<uint64_t>(n);
  }
  if (count > 0 && (!lastElement(*size, *stride, offset, &last) || last >= elements))
    return heap.fail("torch tensor of size " + shapeString(*size) + ", stride " +
                     shapeString(*stride) + " and offset " + std::to_string(offset) +
                     " reads past the " + std::to_string(elements) + " elements of storage '" +
                     key + "'");
  const bool big = heap.options().torch_big_endian;
  if (d.itemsize > 1) d.endian = big ? '>' : '<';
  Result<Array> array = makeError("");
  if (d.kind != 'B' && (count == 0 || isCContiguous(*size, *stride))) {
    const uint8_t* p =
        count == 0 ? nullptr : reinterpret_cast<const uint8_t*>(s.view) + offset * d.itemsize;
    array = decodeArray(heap, d, *size, false, p, count * d.itemsize);
  } else {
    // The gathered bytes (at most the doubles charged next), once both fit.
    const uint64_t gathered = count * (d.kind == 'B' ? 4 : d.itemsize);
    PK_TRY(heap.check(gathered + count * sizeof(double), "strided tensor"));
    MemoryCharge scratch;
    PK_TRY(scratch.add(gathered, heap.context(), "gathering a strided tensor"));
    std::vector<uint8_t> bytes;
    gather(reinterpret_cast<const uint8_t*>(s.view), &d, big, *size, *stride, offset, count,
           &bytes);
    array = decodeArray(heap, d, *size, false, bytes.data(), bytes.size());
  }
  if (!array) return array.error();
  // A tensor's dtype has no byte order (torch.load swaps to native): numpy's name for it.
  if (!array->dtype.empty() && array->dtype[0] == '>') array->dtype[0] = '<';
  if (t.element.kind == 'B') array->dtype = "bfloat16";
  Ref neg;
  if (heap.at(t.metadata).kind == Kind::Dict && dictGet(heap, t.metadata, "neg", &neg) &&
      heap.at(neg).i != 0)
    for (double& v : array->data) v = -v;
  PyObj o;
  o.kind = Kind::NdArray;
  o.array = std::make_unique<Array>(std::move(*array));
  return heap.add(std::move(o));
}

// A storage's persistent id: a tuple of `items` ('storage', type, key,
// location, numel[, view_metadata]; `layout` names them in the error) whose
// type is a known storage class.
struct StorageId {
  Ref type = 0, key_ref = 0;
  std::string key;
  DtypeInfo element;
  int64_t numel = 0;
};

Result<StorageId> storageId(Heap& heap, Ref pid, size_t items, const char* layout) {
  const PyObj& t = heap.at(pid);
  StorageId id;
  std::string tag;
  if (t.kind != Kind::Tuple || t.items.size() != items || !stringValue(heap, t.items[0], &tag) ||
      tag != "storage")
    return heap.fail("persistent id is a " + typeName(heap, pid) + ", expected " + layout);
  const PyObj& type = heap.at(t.items[1]);
  if (type.kind != Kind::Global || type.global != GlobalId::TorchStorageType ||
      !elementOf(type.text, &id.element))
    return heap.fail("torch storage type '" + printable(typeName(heap, t.items[1]), 100) +
                     "' is not supported (complex and quantized tensors are not motion data)");
  if (!stringValue(heap, t.items[2], &id.key) || !intOf(heap.at(t.items[4]), &id.numel) ||
      id.numel < 0)
    return heap.fail("torch storage id has a bad key or element count");
  id.type = t.items[1];
  id.key_ref = t.items[2];
  return id;
}

Result<Ref> tensorFromArgs(Heap& heap, GlobalId id, const std::vector<Ref>& args) {
  const char* name =
      id == GlobalId::TorchRebuildTensorV3 ? "_rebuild_tensor_v3" : "_rebuild_tensor_v2";
  // v2: (storage, offset, size, stride[, requires_grad, hooks[, metadata]]), as
  // _rebuild_tensor's 4; v3: the same 6, dtype[, metadata].
  const size_t needed = id == GlobalId::TorchRebuildTensorV3 ? 7 : 4;
  const size_t most = id == GlobalId::TorchRebuildTensorV3 ? 8 : 7;
  if (args.size() < needed || args.size() > most || args.size() == 5)
    return heap.fail(std::string("torch._utils.") + name + " with " + std::to_string(args.size()) +
                     " arguments is not supported");
  const PyObj& s = heap.at(args[0]);
  if (s.kind != Kind::Instance || s.global != GlobalId::TorchStorage)
    return heap.fail(
        std::string("torch._utils.") + name + "'s storage is a " + typeName(heap, args[0]) +
        ", expected a torch storage (a .pt archive's or torch.storage._load_from_bytes)");
  TensorArgs t{args[0], args[1], args[2], args[3], 0, s.dtype};
  if (id == GlobalId::TorchRebuildTensorV3) {
    const PyObj& dtype = heap.at(args[6]);
    if (dtype.kind != Kind::Global || dtype.global != GlobalId::TorchDtype ||
        !elementOf(dtype.text, &t.element))
      return heap.fail("torch._utils._rebuild_tensor_v3 with dtype " + typeName(heap, args[6]) +
                       " is not supported");
    if (args.size() > 7) t.metadata = args[7];
  } else if (args.size() > 6) {
    t.metadata = args[6];
  }
  return rebuildTensor(heap, t);
}

}  // namespace

bool resolveTorchGlobal(const std::string& module, const std::string& name, GlobalId* id) {
  const bool in_torch = module == "torch" || module.compare(0, 6, "torch.") == 0;
  DtypeInfo d;
  if (name.find("Storage") != std::string::npos) {
    *id = GlobalId::TorchStorageType;  // checked against the known types when used
  } else if (module == "torch._utils" &&
             (name == "_rebuild_tensor_v2" || name == "_rebuild_tensor")) {
    *id = GlobalId::TorchRebuildTensor;
  } else if (module == "torch._utils" && name == "_rebuild_tensor_v3") {
    *id = GlobalId::TorchRebuildTensorV3;
  } else if (module == "torch._utils" &&
             (name == "_rebuild_parameter" || name == "_rebuild_parameter_with_state")) {
    *id = GlobalId::TorchRebuildParameter;
  } else if ((module == "torch._tensor" || module == "torch.tensor") &&
             name == "_rebuild_from_type_v2") {
    *id = GlobalId::TorchRebuildFromType;
  } else if ((module == "torch" || module == "torch._tensor") && name == "Tensor") {
    *id = GlobalId::TorchTensorClass;
  } else if (module == "torch.nn.parameter" && name == "Parameter") {
    *id = GlobalId::TorchTensorClass;
  } else if (module == "torch" && name == "Size") {
    *id = GlobalId::TorchSize;
  } else if (module == "torch" && elementOf(name, &d)) {
    *id = GlobalId::TorchDtype;
  } else {
    return false;
  }
  return in_torch || *id == GlobalId::TorchStorageType;
}

Result<Ref> persistentLoad(Heap& heap, Ref pid) {
  Result<StorageId> id = storageId(heap, pid, 5, "('storage', type, key, location, numel)");
  if (!id) return id.error();
  const std::string& key = id->key;
  const DtypeInfo d = id->element;
  const int64_t numel = id->numel;
  const uint64_t max_numel = UINT64_MAX / static_cast<uint64_t>(d.itemsize);
  const uint64_t nbytes = static_cast<uint64_t>(numel) > max_numel
                              ? UINT64_MAX
                              : static_cast<uint64_t>(numel) * static_cast<uint64_t>(d.itemsize);
  Result<StorageBytes> bytes = heap.options().torch_storage(key, nbytes);
  if (!bytes) return bytes.error();
  if (static_cast<uint64_t>(numel) > bytes->size / static_cast<uint64_t>(d.itemsize))
    return heap.fail("torch storage '" + printable(key) + "' declares " + std::to_string(numel) +
                     " elements of " + std::to_string(d.itemsize) + " bytes; its record has " +
                     std::to_string(bytes->size) + " bytes");
  PK_TRY(heap.charge(sizeof(Ref), "storage"));
  PyObj o;
  o.kind = Kind::Instance;
  o.global = GlobalId::TorchStorage;
  o.text = heap.at(id->type).text;
  o.items = {id->key_ref};  // the key, for errors
  o.view = reinterpret_cast<const char*>(bytes->data);
  o.view_size = static_cast<size_t>(numel) * static_cast<size_t>(d.itemsize);
  o.dtype = d;
  o.i = numel;
  return heap.add(std::move(o));
}

Result<Ref> legacyPersistentLoad(Heap& heap, Ref pid) {
  Result<StorageId> id =
      storageId(heap, pid, 6, "('storage', type, key, location, numel, view_metadata)");
  if (!id) return id.error();
  const std::string& key = id->key;
  const Ref view_metadata = heap.at(pid).items[5];
  // torch's _legacy_save always writes None here (its is_view test compares a storage with itself).
  if (heap.at(view_metadata).kind != Kind::None)
    return heap.fail("torch storage '" + printable(key) + "' is a view (view_metadata " +
                     typeName(heap, view_metadata) + "): not supported");
  PK_TRY(heap.charge(2 * sizeof(Ref), "storage"));
  PyObj o;
  o.kind = Kind::Instance;
  o.global = GlobalId::TorchStorage;
  o.text = heap.at(id->type).text;
  o.items = {id->key_ref};  // the key, for errors and to bind the bytes
  o.dtype = id->element;
  o.i = id->numel;
  Result<Ref> r = heap.add(std::move(o));
  if (r) heap.options().legacy_storages->push_back(*r);
  return r;
}

Result<Ref> callTorchGlobal(Heap& heap, GlobalId id, const std::vector<Ref>& args) {
  switch (id) {
    case GlobalId::TorchRebuildTensor:
    case GlobalId::TorchRebuildTensorV3:
      return tensorFromArgs(heap, id, args);
    case GlobalId::TorchRebuildParameter:
      if (args.empty() || heap.at(args[0]).kind != Kind::NdArray)
        return heap.fail("torch._utils._rebuild_parameter needs a tensor");
      return args[0];
    case GlobalId::TorchSize:
      if (args.size() != 1 || heap.at(args[0]).kind != Kind::Tuple)
        return heap.fail("torch.Size needs a tuple");
      return args[0];
    case GlobalId::TorchRebuildFromType: {
      if (args.size() != 4 || heap.at(args[0]).kind != Kind::Global ||
          heap.at(args[2]).kind != Kind::Tuple)
        return heap.fail("torch._tensor._rebuild_from_type_v2 needs (func, type, args, state)");
      const GlobalId func = heap.at(args[0]).global;
      if (func != GlobalId::TorchRebuildTensor && func != GlobalId::TorchRebuildTensorV3 &&
          func != GlobalId::TorchRebuildParameter)
        return heap.fail("torch._tensor._rebuild_from_type_v2 of '" +
                         printable(heap.at(args[0]).text, 100) + "' is not supported");
      const std::vector<Ref> inner = heap.at(args[2]).items;
      return callTorchGlobal(heap, func, inner);
    }
    default:
      return heap.fail("calling this torch global is not supported");
  }
}

}  // namespace pickle
}  // namespace smpl
