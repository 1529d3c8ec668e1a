// .npz = zip of .npy members (np.savez / np.savez_compressed). The archive is
// memory-mapped (MappedFile; a mapping of a regular file costs address space, not
// memory, and its untouched pages are never read) or, where that fails, read
// through readFileBytes (charged to the memory budget). Members are listed from
// the central directory and inflated one at a time, only when asked for (each
// inflated member is charged to the budget while it lives), and their raw bytes
// released as soon as they are converted.
#include "core/io/npz.h"

#include <algorithm>
#include <set>
#include <utility>

#include "core/io/file_io.h"
#include "core/io/mapped_file.h"
#include "core/io/numpy_dtype.h"
#include "core/io/printable.h"
#include "core/memory_budget.h"

namespace smpl {

// The archive's bytes: a watched read-only mapping of the file or an owned
// copy (MappedFile), or bytes given by the caller (owned).
struct NpzArchive::Storage {
  const uint8_t* data = nullptr;
  size_t size = 0;
  MappedFile file;
  std::vector<uint8_t> owned;
  bool lost() const { return file.lost(); }
};

namespace {

// np.load's NpzFile drops ".npy" from member names to form the keys.
std::string keyOf(const std::string& member) {
  return hasSuffix(member, ".npy") ? member.substr(0, member.size() - 4) : member;
}

// The file mapped (or read, when it cannot be mapped).
Result<std::shared_ptr<NpzArchive::Storage>> mapFile(const std::string& path) {
  auto storage = std::make_shared<NpzArchive::Storage>();
  Result<MappedFile> file = MappedFile::open(path);
  if (!file) return file.error();
  storage->file = std::move(*file);
  storage->data = storage->file.data();
  storage->size = storage->file.size();
  return storage;
}

}  // namespace

Result<NpzArchive> NpzArchive::fromStorage(std::shared_ptr<const Storage> storage,
                                           const std::string& context) {
  Result<std::vector<ZipMember>> members = listZip(storage->data, storage->size, context);
  if (storage->lost()) return storage->file.intact().error();
  if (!members) return members.error();
  NpzArchive a;
  a.storage_ = std::move(storage);
  a.context_ = context;
  std::set<std::string> seen;
  for (ZipMember& m : *members) {
    if (hasSuffix(m.name, "/") && m.usize == 0) continue;  // directory entry
    const std::string key = keyOf(m.name);
    if (!seen.insert(key).second)
      return makeError(context + "/" + printable(m.name) + ": duplicate member '" + printable(key) +
                       "'");
    a.keys_.push_back(key);
    a.members_.push_back(std::move(m));
  }
  return a;
}

Result<NpzArchive> NpzArchive::open(const std::string& path, const std::string& context) {
  Result<std::shared_ptr<Storage>> storage = mapFile(path);
  if (!storage) return storage.error();
  return fromStorage(*storage, context.empty() ? baseName(path) : context);
}

Result<NpzArchive> NpzArchive::fromBytes(const uint8_t* data, size_t size,
                                         const std::string& context) {
  auto storage = std::make_shared<Storage>();
  if (data) storage->owned.assign(data, data + size);
  storage->data = storage->owned.data();
  storage->size = storage->owned.size();
  return fromStorage(storage, context);
}

std::vector<std::string> NpzArchive::keys() const { return keys_; }

bool NpzArchive::has(const std::string& key) const { return find(key) != nullptr; }

std::string NpzArchive::memberName(const std::string& key) const {
  const ZipMember* m = find(key);
  return m ? m->name : std::string();
}

const ZipMember* NpzArchive::find(const std::string& key) const {
  for (size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return &members_[i];
  return nullptr;
}

Status NpzArchive::intact() const {
  if (storage_ && storage_->lost()) return storage_->file.intact().error();
  return Status();
}

Result<ZipEntry> NpzArchive::memberBytes(const std::string& key) const {
  const ZipMember* m = find(key);
  if (!m) return makeError(context_ + ": missing key '" + printable(key) + "'");
  return checked(extractZipMember(storage_->data, storage_->size, *m, context_));
}

Result<ZipBytes> NpzArchive::memberView(const std::string& key) const {
  const ZipMember* m = find(key);
  if (!m) return makeError(context_ + ": missing key '" + printable(key) + "'");
  return checked(viewZipMember(storage_->data, storage_->size, *m, context_));
}

Result<NpyHeaderInfo> NpzArchive::header(const std::string& key) const {
  Result<ZipBytes> e = memberView(key);
  if (!e) return e.error();
  return checked(parseNpyHeader(e->data, e->size, context_ + "/" + printable(find(key)->name)));
}

Result<bool> NpzArchive::isObjectArray(const std::string& key) const {
  const ZipMember* m = find(key);
  if (!m) return makeError(context_ + ": missing key '" + printable(key) + "'");
  constexpr size_t kPeek = 4096;  // numpy's headers are shorter; a longer one takes the full path
  Result<std::vector<uint8_t>> prefix =
      checked(readZipMemberPrefix(storage_->data, storage_->size, *m, kPeek, context_));
  if (!prefix && !intact()) return prefix.error();
  if (prefix) {
    Result<NpyHeaderInfo> h =
        parseNpyHeader(prefix->data(), prefix->size(), context_ + "/" + printable(m->name));
    if (h) return isObjectDescr(h->descr);
  }
  Result<NpyHeaderInfo> h = header(key);
  if (!h) return h.error();
  return isObjectDescr(h->descr);
}

// Before inflating a member: its header (from the first bytes only) tells how
// large the decoded array will be; refuse it against the memory budget now,
// so a small member that widens past the limit costs neither its inflated
// bytes nor its mapped pages. Object arrays are charged by the unpickler.
Status NpzArchive::checkDecodedSize(const std::string& key) const {
  const ZipMember* m = find(key);
  if (!m) return makeError(context_ + ": missing key '" + printable(key) + "'");
  // numpy's headers fit in 4 KiB (it writes < 10000 bytes); only a longer
  // one costs a second, full-size peek (the .npy reader's limit + preamble).
  constexpr size_t kShortPeek = 4096, kHeaderPeek = (1 << 20) + 16;
  const std::string mctx = context_ + "/" + printable(m->name);
  Result<std::vector<uint8_t>> prefix =
      readZipMemberPrefix(storage_->data, storage_->size, *m, kShortPeek, context_);
  if (!prefix) return Status();  // extraction reports the problem in full
  Result<NpyHeaderInfo> h = parseNpyHeader(prefix->data(), prefix->size(), mctx);
  if (!h && prefix->size() == kShortPeek) {
    prefix = readZipMemberPrefix(storage_->data, storage_->size, *m, kHeaderPeek, context_);
    if (!prefix) return Status();
    h = parseNpyHeader(prefix->data(), prefix->size(), mctx);
  }
  if (!h || isObjectDescr(h->descr)) return Status();
  Result<NumpyDtype> t = parseNumpyDescr(h->descr, mctx);
  if (!t) return Status();
  constexpr uint64_t kCap = 1ull << 60;  // saturate: anything this large is refused anyway
  auto times = [&](uint64_t a, uint64_t b) {
    return a == 0 || b == 0 ? 0 : (a > kCap / b ? kCap : a * b);
  };
  uint64_t count = 1;
  for (int64_t d : h->shape) count = times(count, static_cast<uint64_t>(d));
  // A compressed member is inflated whole: one that declares more bytes than
  // its header and array need would only inflate what nothing reads.
  const uint64_t raw = times(count, static_cast<uint64_t>(t->itemsize));
  if (m->method != 0 && m->usize > h->data_offset + raw)
    return makeError(mctx + ": compressed member declares " + std::to_string(m->usize) +
                     " bytes; its array " + shapeString(h->shape) + " needs " +
                     std::to_string(h->data_offset + raw));
  const bool text = t->kind == 'S' || t->kind == 'U';
  const uint64_t decoded = times(count, text ? sizeof(std::string) + t->itemsize : sizeof(double));
  return checkMemory(m->usize + decoded, mctx,
                     "the array " + shapeString(h->shape) + (text ? " as strings" : " as doubles"));
}

Result<Array> NpzArchive::get(const std::string& key) const {
  const ZipMember* m = find(key);
  if (!m) return makeError(context_ + ": missing key '" + printable(key) + "'");
  // The inflated member alone past the budget: refused as inflating, before
  // the header is peeked at (the same check memberBytes makes).
  if (Status st =
          checkMemory(m->usize, context_ + "/" + printable(m->name), "inflating the member");
      !st)
    return st.error();
  if (Status st = checkDecodedSize(key); !st) return checked(Result<Array>(st.error()));
  Result<ZipBytes> e = memberView(key);
  if (!e) return e.error();
  const std::string mctx = context_ + "/" + printable(find(key)->name);
  Result<NpyHeaderInfo> h = parseNpyHeader(e->data, e->size, mctx);
  if (!h) return checked(Result<Array>(h.error()));
  if (isObjectDescr(h->descr))
    return makeError(context_ + ": '" + printable(key) + "' is an object array ('" +
                     printable(h->descr) + "'); expected numbers or text");
  return checked(parseNpy(e->data, e->size, mctx));
}

Result<ArrayDict> NpzArchive::read(const std::vector<std::string>& keys) const {
  ArrayDict arrays;
  for (const std::string& key : keys) {
    if (!has(key) || arrays.count(key)) continue;
    Result<Array> a = get(key);
    if (!a) return a.error();
    arrays.emplace(key, std::move(*a));
  }
  return arrays;
}

Result<ArrayDict> NpzArchive::readAllNumeric() const {
  ArrayDict arrays;
  for (size_t i = 0; i < keys_.size(); ++i) {
    const std::string& key = keys_[i];
    if (Status st = checkDecodedSize(key); !st) return checked(Result<ArrayDict>(st.error()));
    Result<ZipBytes> e = memberView(key);
    if (!e) return e.error();
    const std::string mctx = context_ + "/" + printable(members_[i].name);
    Result<NpyHeaderInfo> h = parseNpyHeader(e->data, e->size, mctx);
    if (!h) return checked(Result<ArrayDict>(h.error()));
    if (isObjectDescr(h->descr)) continue;
    Result<Array> a = checked(parseNpy(e->data, e->size, mctx));
    if (!a) return a.error();
    arrays.emplace(key, std::move(*a));
  }
  return arrays;
}

Result<ArrayDict> parseNpz(const uint8_t* data, size_t size, const std::string& context) {
  Result<NpzArchive> npz = NpzArchive::fromBytes(data, size, context);
  if (!npz) return npz.error();
  return npz->readAllNumeric();
}

Result<ArrayDict> readNpzFile(const std::string& path) {
  Result<NpzArchive> npz = NpzArchive::open(path);
  if (!npz) return npz.error();
  return npz->readAllNumeric();
}

Result<ArrayDict> readNpzFile(const std::string& path, const std::vector<std::string>& keys) {
  Result<NpzArchive> npz = NpzArchive::open(path);
  if (!npz) return npz.error();
  return npz->read(keys);
}

}  // namespace smpl
