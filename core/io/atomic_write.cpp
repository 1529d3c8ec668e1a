// Atomic writes (protocol and naming in file_io.h): temporaries with an
// unpredictable name, created as new files (never an existing name or link)
// and marked live while their writer holds them open; commits serialised by
// a lock on the folder; stale temporaries told from live ones by that mark,
// never by a pid. The OS primitives are core/os/files.h.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <set>
#include <utility>

#include "core/io/content_hash.h"
#include "core/io/file_io.h"
#include "core/os/files.h"
#include "core/os/system.h"
#include "core/parallel.h"

namespace smpl {
namespace {

constexpr const char* kTempInfix = ".smpl.tmp-";
constexpr const char* kBackupSuffix = "-old";
constexpr size_t kNameMax = 255;  // NAME_MAX of Linux file systems
constexpr size_t kTagDigits = 8, kRandomDigits = 16;
// "." + stem + ".smpl.tmp-" + tag + "-" + random + "-old" fits in kNameMax.
constexpr size_t kMaxStem = kNameMax - 1 - 10 - kTagDigits - 1 - kRandomDigits - 4;

Error ioError(const std::string& path, const char* what, const std::string& reason) {
  return makeError(path + ": " + what + ": " + reason);
}

// The output's name cut to kMaxStem bytes, not inside a UTF-8 sequence.
std::string tempStem(const std::string& name) {
  if (name.size() <= kMaxStem) return name;
  size_t cut = kMaxStem;
  while (cut > 0 && (static_cast<uint8_t>(name[cut]) & 0xC0) == 0x80) --cut;
  return name.substr(0, cut);
}

// ".<stem>.smpl.tmp-<tag>-": how every temporary of the output `name` starts.
std::string tempPrefix(const std::string& name) {
  ContentHash tag;
  tag.add(name);
  return "." + tempStem(name) + kTempInfix + tag.hex().substr(0, kTagDigits) + "-";
}

std::atomic<std::string (*)()> g_test_random{nullptr};
std::atomic<void (*)(size_t)> g_commit_hook{nullptr};

// 16 hex digits from the OS's random source. Without entropy (early boot,
// ENOSYS) a hash of time, pid and a counter: still unique enough for the
// create-new retry.
std::string randomDigits() {
  if (std::string(*source)() = g_test_random.load()) return source();
  uint8_t bytes[kRandomDigits / 2];
  if (!os::randomBytes(bytes, sizeof bytes)) {
    static std::atomic<uint64_t> counter{0};
    const uint64_t now =
        static_cast<uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
    const uint64_t parts[4] = {now, 0, os::processId(), counter++};
    ContentHash h;
    h.add(parts, sizeof parts);
    const uint64_t v = h.value();
    std::memcpy(bytes, &v, sizeof bytes);
  }
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (uint8_t b : bytes) out += std::string{kHex[b >> 4], kHex[b & 15]};
  return out;
}

// `entry` placed in the folder of `path` ("dir/entry", or "entry").
std::string besides(const std::string& path, const std::string& entry) {
  const std::string dir = dirName(path);
  if (dir == "." && baseName(path) == path) return entry;  // no folder in the path
  const char last = dir.back();
  return dir + (last == '/' || last == '\\' ? "" : "/") + entry;
}

// A file of the set in its folder: the folder's handle (opened once for the
// whole write) and the file's name there. Every create, link, rename and
// removal below is relative to that handle, so nothing planted or swapped in
// on the folder's path meanwhile can redirect the set.
struct Place {
  const os::Folder* folder = nullptr;
  std::string name;
};

// A temporary being written: its name and the open file that marks it live
// until the commit is over.
struct Temp {
  std::string name;
  os::NewFile file;
};

void closeTemps(const std::vector<Place>& places, std::vector<Temp>* temps, bool remove) {
  for (size_t i = 0; i < temps->size(); ++i) {
    (*temps)[i].file.close();
    if (remove) places[i].folder->remove((*temps)[i].name);
  }
}

// Creates a fresh temporary of `path` (never an existing name or link), under
// the folder's shared lock.
Status createTemp(const std::string& path, const Place& at, Temp* t) {
  for (int attempt = 0; attempt < 64; ++attempt) {
    t->name = baseName(tempPathFor(at.name));
    os::FolderLocks shared(std::vector<const os::Folder*>{at.folder}, false);
    const os::NewFile::Created c = t->file.create(*at.folder, t->name);
    if (c == os::NewFile::Created::Exists) continue;  // taken (or planted): draw another name
    if (c == os::NewFile::Created::Failed)
      return ioError(path, "cannot create temporary file", os::errorText());
    return Status();
  }
  return makeError(path + ": cannot create temporary file: 64 names in a row were taken");
}

Status writeTemp(Temp* t, const FileContent& f) {
  bool written = t->file.writeAll(f.data, f.size);
  for (const ByteSpan& part : f.tail) written = written && t->file.writeAll(part.data, part.size);
  if (!written) return ioError(f.path, "cannot write", os::errorText());
  if (!t->file.sync()) return ioError(f.path, "cannot write (fsync)", os::errorText());
  return Status();
}

// The old file kept while a set of files is replaced.
struct Backup {
  std::string name;      // empty: no backup
  bool existed = false;  // there was an old file (a regular file or a symbolic link)
};

// Only regular files and symbolic links are backed up (a link itself, never
// its target): a directory in the way makes the rename fail, which leaves it
// as it was.
Backup keepBackup(const Place& at, const std::string& backup) {
  if (!at.folder->isFileOrLink(at.name)) return Backup{};
  if (at.folder->hardLink(at.name, backup)) return Backup{backup, true};
  if (at.folder->rename(at.name, backup)) return Backup{backup, true};
  return Backup{"", true};
}

// Undoes a rename of a new file over the place: the backup goes back, or
// the new file is removed when there was no old one.
void restore(const Place& at, const Backup& b) {
  if (!b.name.empty())
    at.folder->rename(b.name, at.name);
  else if (!b.existed)
    at.folder->remove(at.name);
}

// After a failed rename of the temporary: the old file is still in place
// (linked backup) or in the backup (renamed); put it back either way.
void restoreBackup(const Place& at, const Backup& b) {
  if (b.name.empty()) return;
  if (!at.folder->exists(at.name) && at.folder->exists(b.name))
    at.folder->rename(b.name, at.name);
  else
    at.folder->remove(b.name);
}

// Step 2 and 3 of the protocol, under the folders' exclusive lock.
Status commit(const std::vector<FileContent>& files, const std::vector<Place>& places,
              const std::vector<Temp>& temps) {
  std::vector<Backup> backups;
  for (size_t i = 0; i < files.size(); ++i) {
    const Place& at = places[i];
    const Backup b = keepBackup(at, temps[i].name + kBackupSuffix);
    if (!at.folder->rename(temps[i].name, at.name)) {
      Status st =
          ioError(files[i].path, "cannot rename temporary file into place", os::errorText());
      restoreBackup(at, b);  // rename left the old file as it was
      for (size_t j = i; j-- > 0;) restore(places[j], backups[j]);
      for (size_t j = i; j < files.size(); ++j) places[j].folder->remove(temps[j].name);
      return st;
    }
    backups.push_back(b);
    if (void (*hook)(size_t) = g_commit_hook.load()) hook(i);
  }
  for (size_t i = 0; i < backups.size(); ++i)
    if (!backups[i].name.empty()) places[i].folder->remove(backups[i].name);
  return Status();
}

// Opens the folder of each file once (files in one folder share its handle).
// Errors name the file: "<path>: cannot create temporary file: <reason>".
Status openFolders(const std::vector<FileContent>& files, std::vector<os::Folder>* folders,
                   std::vector<Place>* places) {
  std::vector<std::string> dirs;
  for (const FileContent& f : files) {
    const std::string dir = dirName(f.path);
    if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
  }
  folders->resize(dirs.size());  // never resized again: places point into it
  for (size_t i = 0; i < dirs.size(); ++i) {
    if ((*folders)[i].open(dirs[i])) continue;
    for (const FileContent& f : files)
      if (dirName(f.path) == dirs[i])
        return ioError(f.path, "cannot create temporary file", os::errorText());
  }
  for (const FileContent& f : files) {
    const size_t k = std::find(dirs.begin(), dirs.end(), dirName(f.path)) - dirs.begin();
    places->push_back(Place{&(*folders)[k], baseName(f.path)});
  }
  return Status();
}

// `entry` is a temporary (or backup) of one of the outputs whose temporary
// names start with one of `prefixes`: prefix, 16 hex digits, optional "-old".
bool isTempOf(const std::string& entry, const std::vector<std::string>& prefixes) {
  for (const std::string& p : prefixes) {
    if (entry.compare(0, p.size(), p) != 0) continue;
    std::string rest = entry.substr(p.size());
    if (hasSuffix(rest, kBackupSuffix)) rest.resize(rest.size() - std::strlen(kBackupSuffix));
    if (rest.size() == kRandomDigits &&
        rest.find_first_not_of("0123456789abcdef") == std::string::npos)
      return true;
  }
  return false;
}

}  // namespace

std::string tempPathFor(const std::string& path) {
  return besides(path, tempPrefix(baseName(path)) + randomDigits());
}

void setTempRandomForTesting(std::string (*source)()) { g_test_random.store(source); }

void setCommitHookForTesting(void (*hook)(size_t)) { g_commit_hook.store(hook); }

Status writeFileAtomic(const std::string& path, const void* data, size_t size) {
  return writeFilesTogether({FileContent{path, data, size}});
}

size_t FileContent::totalSize() const {
  size_t n = size;
  for (const ByteSpan& part : tail) n += part.size;
  return n;
}

namespace {

// Creates and writes the temporary of each of `files` (appended to `temps`).
Status writeTemps(const std::vector<FileContent>& files, const std::vector<Place>& places,
                  std::vector<Temp>* temps) {
  for (size_t i = 0; i < files.size(); ++i) {
    temps->emplace_back();
    Status st = createTemp(files[i].path, places[temps->size() - 1], &temps->back());
    if (!st) temps->pop_back();  // nothing created: its last name may be someone else's file
    if (st) st = writeTemp(&temps->back(), files[i]);
    if (!st) return st;
  }
  return Status();
}

// The protocol of writeFilesTogether on `files`, the last one's bytes made
// by `make_record` (null: every file's bytes are given) beside the others'
// writes when `together`.
Status writeSet(std::vector<FileContent> files, const std::function<std::string()>& make_record,
                bool together) {
  for (const FileContent& f : files)
    if (baseName(f.path).size() > kNameMax)
      return ioError(f.path, "cannot create", std::strerror(ENAMETOOLONG));
  std::vector<os::Folder> folders;
  std::vector<Place> places;
  if (Status st = openFolders(files, &folders, &places); !st) return st;
  std::vector<Temp> temps;
  temps.reserve(files.size());
  Status st;
  if (make_record) {
    const std::vector<FileContent> given(files.begin(), files.end() - 1);
    std::string record;
    try {
      runTogether(
          together, [&] { st = writeTemps(given, places, &temps); },
          [&] { record = make_record(); });
    } catch (...) {
      closeTemps(places, &temps, true);
      throw;
    }
    files.back().data = record.data();
    files.back().size = record.size();
    if (st) st = writeTemps({files.back()}, places, &temps);
  } else {
    st = writeTemps(files, places, &temps);
  }
  if (!st) {
    closeTemps(places, &temps, true);
    return st;
  }
  std::vector<const os::Folder*> held;
  for (const os::Folder& f : folders) held.push_back(&f);
  {
    os::FolderLocks exclusive(held, true);
    st = commit(files, places, temps);
    if (st) exclusive.sync();
  }
  closeTemps(places, &temps, false);  // renamed into place, or already removed by commit()
  return st;
}

}  // namespace

Status writeFilesTogether(const std::vector<FileContent>& files) {
  return writeSet(files, nullptr, false);
}

Status writeFilesWithRecord(const std::vector<FileContent>& files, const std::string& record_path,
                            const std::function<std::string()>& make_record, bool together) {
  std::vector<FileContent> all = files;
  all.push_back(FileContent{record_path, nullptr, 0});
  return writeSet(std::move(all), make_record, together);
}

int removeStaleTemps(const std::string& dir, const std::vector<std::string>& names) {
  std::vector<std::string> prefixes;
  for (const std::string& n : std::set<std::string>(names.begin(), names.end()))
    prefixes.push_back(tempPrefix(n));
  os::Folder folder;
  if (!folder.open(dir)) return 0;
  os::FolderLocks exclusive(std::vector<const os::Folder*>{&folder}, true);  // no temporary is
  int removed = 0;  // between its creation and its mark meanwhile
  for (const std::string& entry : folder.list())
    if (isTempOf(entry, prefixes) && folder.removeIfUnused(entry)) ++removed;
  return removed;
}

}  // namespace smpl
