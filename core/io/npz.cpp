// .npz = zip of .npy members (np.savez / np.savez_compressed). The archive is
// memory-mapped (POSIX) or read once; members are listed from the central
// directory and inflated one at a time, only when asked for, and their raw
// bytes released as soon as they are converted.
#include "core/io/npz.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <set>
#include <utility>

#include "core/io/file_io.h"

namespace smpl {

// The archive's bytes: a read-only mapping of the file, or an owned copy.
struct NpzArchive::Storage {
  const uint8_t* data = nullptr;
  size_t size = 0;
  void* mapping = nullptr;
  std::vector<uint8_t> owned;
  ~Storage() {
    if (mapping) munmap(mapping, size);
  }
};

namespace {

// np.load's NpzFile drops ".npy" from member names to form the keys.
std::string keyOf(const std::string& member) {
  return hasSuffix(member, ".npy") ? member.substr(0, member.size() - 4) : member;
}

// mmap the file read-only; an empty or unmappable file falls back to reading it.
Result<std::shared_ptr<NpzArchive::Storage>> mapFile(const std::string& path) {
  auto storage = std::make_shared<NpzArchive::Storage>();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    void* m = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (m != MAP_FAILED) {
      storage->mapping = m;
      storage->data = static_cast<const uint8_t*>(m);
      storage->size = static_cast<size_t>(st.st_size);
    }
  }
  if (fd >= 0) ::close(fd);
  if (storage->mapping) return storage;
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  storage->owned = std::move(*bytes);
  storage->data = storage->owned.data();
  storage->size = storage->owned.size();
  return storage;
}

}  // namespace

Result<NpzArchive> NpzArchive::fromStorage(std::shared_ptr<const Storage> storage, const std::string& context) {
  Result<std::vector<ZipMember>> members = listZip(storage->data, storage->size, context);
  if (!members) return members.error();
  NpzArchive a;
  a.storage_ = std::move(storage);
  a.context_ = context;
  std::set<std::string> seen;
  for (ZipMember& m : *members) {
    if (hasSuffix(m.name, "/") && m.usize == 0) continue;  // directory entry
    const std::string key = keyOf(m.name);
    if (!seen.insert(key).second) return makeError(context + "/" + m.name + ": duplicate member '" + key + "'");
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

Result<NpzArchive> NpzArchive::fromBytes(const uint8_t* data, size_t size, const std::string& context) {
  auto storage = std::make_shared<Storage>();
  if (data) storage->owned.assign(data, data + size);
  storage->data = storage->owned.data();
  storage->size = storage->owned.size();
  return fromStorage(storage, context);
}

std::vector<std::string> NpzArchive::keys() const { return keys_; }

bool NpzArchive::has(const std::string& key) const { return find(key) != nullptr; }

const ZipMember* NpzArchive::find(const std::string& key) const {
  for (size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i] == key) return &members_[i];
  return nullptr;
}

Result<std::vector<uint8_t>> NpzArchive::memberBytes(const std::string& key) const {
  const ZipMember* m = find(key);
  if (!m) return makeError(context_ + ": missing key '" + key + "'");
  return extractZipMember(storage_->data, storage_->size, *m, context_);
}

Result<NpyHeaderInfo> NpzArchive::header(const std::string& key) const {
  Result<std::vector<uint8_t>> bytes = memberBytes(key);
  if (!bytes) return bytes.error();
  return parseNpyHeader(bytes->data(), bytes->size(), context_ + "/" + find(key)->name);
}

Result<Array> NpzArchive::get(const std::string& key) const {
  Result<std::vector<uint8_t>> bytes = memberBytes(key);
  if (!bytes) return bytes.error();
  const std::string mctx = context_ + "/" + find(key)->name;
  Result<NpyHeaderInfo> h = parseNpyHeader(bytes->data(), bytes->size(), mctx);
  if (!h) return h.error();
  if (isObjectDescr(h->descr))
    return makeError(context_ + ": '" + key + "' is an object array ('" + h->descr +
                     "'); expected numbers or text");
  return parseNpy(bytes->data(), bytes->size(), mctx);
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
    Result<std::vector<uint8_t>> bytes = memberBytes(key);
    if (!bytes) return bytes.error();
    const std::string mctx = context_ + "/" + members_[i].name;
    Result<NpyHeaderInfo> h = parseNpyHeader(bytes->data(), bytes->size(), mctx);
    if (!h) return h.error();
    if (isObjectDescr(h->descr)) continue;
    Result<Array> a = parseNpy(bytes->data(), bytes->size(), mctx);
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
