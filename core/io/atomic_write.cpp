// Atomic writes (protocol and naming in file_io.h): temporaries with an
// unpredictable name, created with O_EXCL | O_NOFOLLOW and held by an flock
// while their writer lives; commits serialised by an flock on the folder;
// stale temporaries told from live ones by that lock, never by a pid.
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <set>
#include <utility>

#include "core/io/content_hash.h"
#include "core/io/file_io.h"

namespace smpl {
namespace {

constexpr const char* kTempInfix = ".smpl.tmp-";
constexpr const char* kBackupSuffix = "-old";
constexpr size_t kNameMax = 255;  // NAME_MAX of Linux file systems
constexpr size_t kTagDigits = 8, kRandomDigits = 16;
// "." + stem + ".smpl.tmp-" + tag + "-" + random + "-old" fits in kNameMax.
constexpr size_t kMaxStem = kNameMax - 1 - 10 - kTagDigits - 1 - kRandomDigits - 4;

Error ioError(const std::string& path, const char* what, int err) {
  return makeError(path + ": " + what + ": " + std::strerror(err));
}

int flockRetry(int fd, int operation) {
  int r;
  while ((r = ::flock(fd, operation)) != 0 && errno == EINTR) {
  }
  return r;
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

// 16 hex digits from getrandom(2). Without entropy (early boot, ENOSYS) a
// hash of time, pid and a counter: still unique enough for O_EXCL to retry.
std::string randomDigits() {
  if (std::string(*source)() = g_test_random.load()) return source();
  uint8_t bytes[kRandomDigits / 2];
  if (::getrandom(bytes, sizeof bytes, GRND_NONBLOCK) != static_cast<ssize_t>(sizeof bytes)) {
    static std::atomic<uint64_t> counter{0};
    struct timespec ts {};
    ::clock_gettime(CLOCK_REALTIME, &ts);
    const uint64_t parts[4] = {static_cast<uint64_t>(ts.tv_sec), static_cast<uint64_t>(ts.tv_nsec),
                               static_cast<uint64_t>(::getpid()), counter++};
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
  if (path.find('/') == std::string::npos) return entry;
  const std::string dir = dirName(path);
  return (dir == "/" ? "" : dir) + "/" + entry;
}

// Exclusive (or shared) flocks on folders, released when destroyed. Folders
// are locked in (device, inode) order, once each, so two writers of the same
// set never wait for each other crosswise. Best effort: a folder that cannot
// be opened or locked (EACCES, ENOLCK) is used unlocked.
class FolderLocks {
 public:
  FolderLocks(const std::vector<std::string>& dirs, int operation) {
    std::vector<std::pair<std::pair<dev_t, ino_t>, int>> open;
    for (const std::string& dir : dirs) {
      const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      struct stat st {};
      if (fd < 0) continue;
      if (::fstat(fd, &st) != 0) {
        ::close(fd);
        continue;
      }
      open.push_back({{st.st_dev, st.st_ino}, fd});
    }
    std::sort(open.begin(), open.end());
    for (size_t i = 0; i < open.size(); ++i) {
      if (i > 0 && open[i].first == open[i - 1].first) {
        ::close(open[i].second);  // the same folder by another path: one lock is enough
        continue;
      }
      flockRetry(open[i].second, operation);
      fds_.push_back(open[i].second);
    }
  }
  ~FolderLocks() {
    for (int fd : fds_) ::close(fd);  // closing releases the flock
  }
  FolderLocks(const FolderLocks&) = delete;
  FolderLocks& operator=(const FolderLocks&) = delete;
  // Makes the renames durable; best effort, a failure here loses nothing.
  void sync() const {
    for (int fd : fds_) ::fsync(fd);
  }

 private:
  std::vector<int> fds_;
};

// A temporary being written: its name and the descriptor that holds its
// flock (and so marks it live) until the commit is over.
struct Temp {
  std::string path;
  int fd = -1;
};

void closeTemps(std::vector<Temp>* temps, bool remove) {
  for (Temp& t : *temps) {
    if (remove) ::unlink(t.path.c_str());
    if (t.fd >= 0) ::close(t.fd);
    t.fd = -1;
  }
}

// Creates a fresh temporary of `path` (never an existing name: O_EXCL, and
// O_NOFOLLOW for good measure) and locks it, under the folder's shared lock.
Result<Temp> createTemp(const std::string& path) {
  for (int attempt = 0; attempt < 64; ++attempt) {
    Temp t{tempPathFor(path), -1};
    FolderLocks shared({dirName(path)}, LOCK_SH);
    t.fd = ::open(t.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (t.fd < 0 && errno == EEXIST) continue;  // taken (or planted): draw another name
    if (t.fd < 0) return ioError(path, "cannot create temporary file", errno);
    flockRetry(t.fd, LOCK_EX | LOCK_NB);  // a new inode: nobody else can hold it
    return t;
  }
  return makeError(path + ": cannot create temporary file: 64 names in a row were taken");
}

Status writeAll(int fd, const std::string& path, const uint8_t* p, size_t size) {
  while (size > 0) {
    ssize_t n = ::write(fd, p, std::min<size_t>(size, 1u << 30));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return ioError(path, "cannot write", errno);
    p += n;
    size -= static_cast<size_t>(n);
  }
  return Status();
}

Status writeTemp(const Temp& t, const FileContent& f) {
  if (Status st = writeAll(t.fd, f.path, static_cast<const uint8_t*>(f.data), f.size); !st)
    return st;
  if (Status st = writeAll(t.fd, f.path, static_cast<const uint8_t*>(f.tail), f.tail_size); !st)
    return st;
  if (::fsync(t.fd) != 0) return ioError(f.path, "cannot write (fsync)", errno);
  return Status();
}

// The old file kept while a set of files is replaced.
struct Backup {
  std::string path;      // empty: no backup
  bool existed = false;  // there was an old file (a regular file or a symbolic link)
};

// Only regular files and symbolic links are backed up (linkat without
// AT_SYMLINK_FOLLOW links a symbolic link itself, never its target): a
// directory in the way makes the rename fail, which leaves it as it was.
Backup keepBackup(const std::string& path, const std::string& backup) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 || !(S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)))
    return Backup{};
  if (::linkat(AT_FDCWD, path.c_str(), AT_FDCWD, backup.c_str(), 0) == 0)
    return Backup{backup, true};
  if (::rename(path.c_str(), backup.c_str()) == 0) return Backup{backup, true};
  return Backup{"", true};
}

// Undoes a rename of a new file over `path`: the backup goes back in place,
// or the new file is removed when there was no old one.
void restore(const std::string& path, const Backup& b) {
  if (!b.path.empty())
    ::rename(b.path.c_str(), path.c_str());
  else if (!b.existed)
    ::unlink(path.c_str());
}

// After a failed rename of the temporary: the old file is still in `path`
// (linked backup) or in the backup (renamed); put it back either way.
void restoreBackup(const std::string& path, const Backup& b) {
  if (b.path.empty()) return;
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 && ::lstat(b.path.c_str(), &st) == 0)
    ::rename(b.path.c_str(), path.c_str());
  else
    ::unlink(b.path.c_str());
}

// Step 2 and 3 of the protocol, under the folders' exclusive lock.
Status commit(const std::vector<FileContent>& files, const std::vector<Temp>& temps) {
  std::vector<Backup> backups;
  for (size_t i = 0; i < files.size(); ++i) {
    const Backup b = keepBackup(files[i].path, temps[i].path + kBackupSuffix);
    if (::rename(temps[i].path.c_str(), files[i].path.c_str()) != 0) {
      Status st = ioError(files[i].path, "cannot rename temporary file into place", errno);
      restoreBackup(files[i].path, b);  // rename left the old file as it was
      for (size_t j = i; j-- > 0;) restore(files[j].path, backups[j]);
      for (size_t j = i; j < files.size(); ++j) ::unlink(temps[j].path.c_str());
      return st;
    }
    backups.push_back(b);
    if (void (*hook)(size_t) = g_commit_hook.load()) hook(i);
  }
  for (const Backup& b : backups)
    if (!b.path.empty()) ::unlink(b.path.c_str());
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

// Removes the regular file `path` if no one holds an flock on it (its writer
// is gone). A link, a folder or a file that cannot be opened is left alone.
bool removeIfUnlocked(const std::string& path) {
  struct stat before {
  }, now{};
  if (::lstat(path.c_str(), &before) != 0 || !S_ISREG(before.st_mode)) return false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  bool removed = false;
  if (::fstat(fd, &now) == 0 && now.st_dev == before.st_dev && now.st_ino == before.st_ino &&
      flockRetry(fd, LOCK_EX | LOCK_NB) == 0)
    removed = ::unlink(path.c_str()) == 0;
  ::close(fd);
  return removed;
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

Status writeFilesTogether(const std::vector<FileContent>& files) {
  for (const FileContent& f : files)
    if (baseName(f.path).size() > kNameMax) return ioError(f.path, "cannot create", ENAMETOOLONG);
  std::vector<Temp> temps;
  for (const FileContent& f : files) {
    Result<Temp> t = createTemp(f.path);
    if (t) temps.push_back(*t);
    Status st = t ? writeTemp(temps.back(), f) : Status(t.error());
    if (!st) {
      closeTemps(&temps, true);
      return st;
    }
  }
  std::vector<std::string> dirs;
  for (const FileContent& f : files) dirs.push_back(dirName(f.path));
  Status st;
  {
    FolderLocks exclusive(dirs, LOCK_EX);
    st = commit(files, temps);
    if (st) exclusive.sync();
  }
  closeTemps(&temps, false);  // renamed into place, or already removed by commit()
  return st;
}

int removeStaleTemps(const std::string& dir, const std::vector<std::string>& names) {
  std::vector<std::string> prefixes;
  for (const std::string& n : std::set<std::string>(names.begin(), names.end()))
    prefixes.push_back(tempPrefix(n));
  FolderLocks exclusive({dir}, LOCK_EX);  // no temporary is between creation and its flock
  DIR* d = ::opendir(dir.c_str());
  if (!d) return 0;
  int removed = 0;
  while (dirent* e = ::readdir(d)) {
    const std::string entry = e->d_name;
    if (isTempOf(entry, prefixes) && removeIfUnlocked(dir + "/" + entry)) ++removed;
  }
  ::closedir(d);
  return removed;
}

}  // namespace smpl
