// torch.storage._load_from_bytes(b): how a torch storage pickles itself
// outside torch.save (np.save of a dict of tensors as TRAM writes it,
// pickle.dump of a tensor). Tensor.__reduce_ex__ gives
// torch._utils._rebuild_tensor_v2(storage, offset, size, stride, ...) and the
// storage's __reduce__ gives _load_from_bytes(b), where b is
// torch.save(storage, _use_new_zipfile_serialization=False): torch's legacy
// serialization (torch/storage.py and torch/serialization.py _legacy_save /
// _legacy_load, torch 1.13; the same in torch 2.x on GitHub pytorch/pytorch):
//   1. pickle of the magic number 0x1950a86a20f9469cfc6c (protocol 2: the
//      bytes isLegacyTorchFile checks, then STOP)
//   2. pickle of the protocol version, 1001
//   3. pickle of a sys-info dict (protocol_version, little_endian,
//      type_sizes), which torch's reader ignores
//   4. pickle of the storage, as BINPERSID of ('storage', torch.FloatStorage
//      (or another legacy class; torch.UntypedStorage in torch 2.x for dtypes
//      without one, counted in bytes), key, location, numel, view_metadata);
//      view_metadata is always None (_legacy_save's is_view is never true)
//   5. pickle of the sorted list of storage keys
//   6. per key: the element count as little-endian int64, then the elements.
// The elements are little-endian whatever sys_info says: torch's writer
// converts on big-endian machines (torch/csrc/serialization.cpp
// THPStorage_writeFileRaw), and its reader requires the count to equal the
// declared numel ("storage has wrong byte size").
// Each pickle runs in the same data-only VM and heap (the outer pickle's
// limits and budget); the storages view b's bytes, which the outer pickle
// already charged. A _load_from_bytes inside b is refused (resolveGlobal).
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/io/pickle/pickle_internal.h"
#include "core/io/pickle/pickle_tree.h"
#include "core/io/printable.h"

namespace smpl {
namespace pickle {
namespace {

constexpr int64_t kLegacyProtocol = 1001;
constexpr size_t kMagicPickle = 15;  // PROTO 2, LONG1 of 10 bytes, STOP
constexpr uint64_t kMapEntry = 64;   // what a hash map entry of a key costs, roughly

class LegacyReader {
 public:
  LegacyReader(Heap& heap, std::string_view bytes, const PickleLimits& limits)
      : heap_(heap),
        data_(reinterpret_cast<const uint8_t*>(bytes.data())),
        size_(bytes.size()),
        limits_(limits) {}
  Result<Ref> read();

 private:
  Result<Ref> next(const char* what);
  Status header();
  Status bindStorages(Ref keys);
  Status bindOne(const std::string& key, const std::vector<Ref>& named);
  Error fail(const std::string& message) const {
    return heap_.fail("torch.storage._load_from_bytes: " + message);
  }
  // An error of a pickle inside the bytes, said to be there.
  Error inside(const Error& e, const char* what) const {
    const std::string prefix = heap_.context() + ": ";
    if (e.message.compare(0, prefix.size(), prefix) != 0) return e;
    return fail(std::string("in its ") + what + " pickle (at byte " + std::to_string(pos_) +
                " of its " + std::to_string(size_) + "): " + e.message.substr(prefix.size()));
  }

  Heap& heap_;
  const uint8_t* data_;
  size_t size_;
  const PickleLimits& limits_;
  size_t pos_ = 0;
  std::vector<Ref> storages_;  // declared by the object pickle, in order
};

// The next pickle of the stream, from pos_.
Result<Ref> LegacyReader::next(const char* what) {
  if (pos_ >= size_)
    return fail("its bytes end before the " + std::string(what) + " pickle (" +
                std::to_string(size_) + " bytes)");
  size_t end = pos_;
  Result<Ref> r = runPickleAt(heap_, data_, size_, pos_, limits_, &end);
  if (!r) return inside(r.error(), what);
  pos_ = end;
  return r;
}

Status LegacyReader::header() {
  if (!isLegacyTorchFile(data_, size_) || size_ < kMagicPickle || data_[kMagicPickle - 1] != '.')
    return fail("its bytes do not start with torch's magic number 0x1950a86a20f9469cfc6c");
  pos_ = kMagicPickle;
  Result<Ref> version = next("protocol version");
  if (!version) return version.error();
  const PyObj& v = heap_.at(*version);
  if (v.kind != Kind::Int || v.i != kLegacyProtocol)
    return fail("protocol version is " +
                (v.kind == Kind::Int ? std::to_string(v.i) : "a " + typeName(heap_, *version)) +
                ", expected 1001");
  Result<Ref> sys_info = next("sys-info");
  if (!sys_info) return sys_info.error();
  if (heap_.at(*sys_info).kind != Kind::Dict)
    return fail("sys-info is a " + typeName(heap_, *sys_info) + ", expected a dict");
  return Status::success();
}

// Sets a VmOptions flag or pointer for one scope.
template <typename T>
class Scoped {
 public:
  Scoped(T* field, T value) : field_(field), old_(*field) { *field = value; }
  ~Scoped() { *field_ = old_; }
  Scoped(const Scoped&) = delete;
  Scoped& operator=(const Scoped&) = delete;

 private:
  T* field_;
  T old_;
};

Result<Ref> LegacyReader::read() {
  Scoped<bool> inside(&heap_.options().inside_load_from_bytes, true);
  PK_TRY(header());
  Result<Ref> object = makeError("");
  {
    Scoped<std::vector<Ref>*> declaring(&heap_.options().legacy_storages, &storages_);
    object = next("storage");
  }
  if (!object) return object.error();
  const PyObj& o = heap_.at(*object);
  if (o.kind != Kind::Instance || o.global != GlobalId::TorchStorage)
    return fail("its pickle holds a " + typeName(heap_, *object) + ", expected a storage");
  Result<Ref> keys = next("storage keys");
  if (!keys) return keys.error();
  PK_TRY(bindStorages(*keys));
  if (pos_ != size_)
    return fail(std::to_string(size_ - pos_) + " bytes follow the last storage's data");
  return *object;
}

Status LegacyReader::bindStorages(Ref keys) {
  const PyObj& list = heap_.at(keys);
  if (list.kind != Kind::List)
    return fail("the storage keys are a " + typeName(heap_, keys) + ", expected a list");
  // key -> the storages declared with it (hash maps: a hostile list of many keys stays linear).
  std::unordered_map<std::string, std::vector<Ref>> declared;
  for (Ref s : storages_) {
    const std::string_view key = heap_.at(heap_.at(s).items[0]).bytes();
    PK_TRY(heap_.charge(kMapEntry + key.size(), "storage key"));
    declared[std::string(key)].push_back(s);
  }
  std::unordered_set<std::string> seen;
  std::string key;
  for (Ref k : list.items) {
    if (!stringValue(heap_, k, &key))
      return fail("a storage key is a " + typeName(heap_, k) + ", expected str");
    if (!seen.insert(key).second)
      return fail("storage key '" + printable(key) + "' is listed twice");
    PK_TRY(heap_.charge(kMapEntry + key.size(), "storage key"));
    auto it = declared.find(key);
    if (it == declared.end()) return fail("storage key '" + printable(key) + "' names no storage");
    PK_TRY(bindOne(key, it->second));
  }
  for (Ref s : storages_)
    if (!heap_.at(s).view)
      return fail("storage '" + printable(std::string(heap_.at(heap_.at(s).items[0]).bytes())) +
                  "' has no data (its key is not in the key list)");
  return Status::success();
}

// The element count and elements of storage `key`, bound to every storage
// the pickle declared with that key (`named`, at least one).
Status LegacyReader::bindOne(const std::string& key, const std::vector<Ref>& named) {
  const std::string name = "storage '" + printable(key) + "'";
  if (size_ - pos_ < 8)
    return fail("its bytes end at byte " + std::to_string(size_) +
                ", before the element count of " + name);
  uint64_t count = 0;
  for (int b = 7; b >= 0; --b) count = count << 8 | data_[pos_ + b];
  pos_ += 8;
  const PyObj& first = heap_.at(named[0]);
  const uint64_t itemsize = static_cast<uint64_t>(first.dtype.itemsize);
  if (count > (size_ - pos_) / itemsize)
    return fail(name + " has " + std::to_string(count) + " elements of " +
                std::to_string(itemsize) + " bytes, but only " + std::to_string(size_ - pos_) +
                " bytes follow");
  for (Ref s : named) {
    PyObj& o = heap_.at(s);
    if (static_cast<uint64_t>(o.i) != count || o.dtype.itemsize != first.dtype.itemsize)
      return fail(name + " is declared with " + std::to_string(o.i) + " elements of " +
                  std::to_string(o.dtype.itemsize) + " bytes, but its data has " +
                  std::to_string(count) + " of " + std::to_string(itemsize));
    o.view = reinterpret_cast<const char*>(data_ + pos_);
    o.view_size = static_cast<size_t>(count * itemsize);
  }
  pos_ += static_cast<size_t>(count * itemsize);
  return Status::success();
}

}  // namespace

Result<Ref> loadFromBytes(Heap& heap, Ref args, const PickleLimits& limits) {
  const PyObj& a = heap.at(args);
  if (a.kind != Kind::Tuple || a.items.size() != 1 || heap.at(a.items[0]).kind != Kind::Bytes)
    return heap.fail("torch.storage._load_from_bytes needs one bytes argument");
  if (heap.options().inside_load_from_bytes)  // resolveGlobal refuses it first
    return heap.fail("torch.storage._load_from_bytes inside the bytes of another");
  // The bytes stay where they are (the outer pickle, or this heap's object). Each call
  // counts them against the pickle's bound: the memo can name one byte string many times,
  // and its pickles run again each time.
  const std::string_view bytes = heap.at(a.items[0]).bytes();
  PK_TRY(heap.count(bytes.size(), "torch legacy storage bytes"));
  LegacyReader reader(heap, bytes, limits);
  return reader.read();
}

}  // namespace pickle
}  // namespace smpl
