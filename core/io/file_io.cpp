// Whole-file reads and atomic writes on POSIX file descriptors, so that every
// failure can be reported with strerror and a failed write leaves no file.
#include "core/io/file_io.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <set>

#include "core/memory_budget.h"

namespace smpl {
namespace {

Error ioError(const std::string& path, const char* what, int err) {
  return makeError(path + ": " + what + ": " + std::strerror(err));
}

// Closes the descriptor on every return path.
struct Fd {
  int fd = -1;
  explicit Fd(int f) : fd(f) {}
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
};

// Reads until EOF; works for regular files, pipes and /dev/stdin alike.
// `hint` (the file size when known) sizes the buffer so a regular file is read
// without regrowing: the +1 leaves room for the read that returns EOF.
// Every buffer size is checked against the memory budget first, so an endless
// pipe ends with an error, not with all of memory.
Status readAll(int fd, const std::string& path, size_t hint, std::vector<uint8_t>& out) {
  size_t used = 0;
  const size_t first = std::max<size_t>(hint + 1, 65536);
  if (Status st = checkMemory(first, path, "reading the file"); !st) return st;
  out.resize(first);
  for (;;) {
    if (used == out.size()) {
      if (Status st = checkMemory(out.size() * 2, path, "reading the file"); !st) return st;
      out.resize(out.size() * 2);
    }
    ssize_t n = ::read(fd, out.data() + used, out.size() - used);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return ioError(path, "cannot read", errno);
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  out.resize(used);
  return Status();
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

const char* fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

// Makes the rename itself durable; best effort, a failure here loses nothing.
void syncDirectory(const std::string& path) {
  Fd dir(::open(dirName(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.fd >= 0) ::fsync(dir.fd);
}

Status writeTemp(const std::string& tmp, const std::string& path, const void* data, size_t size) {
  Fd fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
  if (fd.fd < 0) return ioError(path, "cannot create temporary file", errno);
  if (Status st = writeAll(fd.fd, path, static_cast<const uint8_t*>(data), size); !st) return st;
  if (::fsync(fd.fd) != 0) return ioError(path, "cannot write (fsync)", errno);
  int f = fd.fd;
  fd.fd = -1;
  if (::close(f) != 0) return ioError(path, "cannot write (close)", errno);
  return Status();
}

constexpr const char* kTempInfix = ".smpl.tmp-";

// The old file kept while a set of files is replaced (writeFilesTogether).
struct Backup {
  std::string path;  // empty: there was no old file
};

// Only regular files and symlinks are backed up: a directory in the way makes
// the rename fail, which leaves it as it was.
Backup keepBackup(const std::string& path, const std::string& backup) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 || !(S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)))
    return Backup{};
  ::unlink(backup.c_str());
  if (::link(path.c_str(), backup.c_str()) == 0) return Backup{backup};
  if (::rename(path.c_str(), backup.c_str()) == 0) return Backup{backup};
  return Backup{};
}

// Undoes a rename of a new file over `path`: the backup goes back in place,
// or the new file is removed when there was no old one.
void restore(const std::string& path, const Backup& b) {
  if (b.path.empty())
    ::unlink(path.c_str());
  else
    ::rename(b.path.c_str(), path.c_str());
}

// After a failed rename of the temporary: the old file is still in `path`
// (linked backup) or in the backup (renamed); put it back either way.
void restoreBackup(const std::string& path, const std::string& backup) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 && ::lstat(backup.c_str(), &st) == 0)
    ::rename(backup.c_str(), path.c_str());
  else
    ::unlink(backup.c_str());
}

// ".<name>.smpl.tmp-<pid>[suffix]" with <name> in `ours` -> pid.
bool tempOwner(const std::string& entry, const std::set<std::string>& ours, long* pid) {
  if (entry.size() < 2 || entry[0] != '.') return false;
  const size_t infix = entry.rfind(kTempInfix);
  if (infix == std::string::npos || infix < 1 || !ours.count(entry.substr(1, infix - 1)))
    return false;
  const char* digits = entry.c_str() + infix + std::strlen(kTempInfix);
  char* end = nullptr;
  *pid = std::strtol(digits, &end, 10);
  return end != digits && *pid > 0;
}

bool processAlive(long pid) {
  if (pid == static_cast<long>(::getpid())) return true;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

bool olderThanADay(const std::string& path) {
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 && std::time(nullptr) - st.st_mtime > 24 * 3600;
}

}  // namespace

Result<std::vector<uint8_t>> readFileBytes(const std::string& path) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.fd < 0) return ioError(path, "cannot open", errno);
  std::vector<uint8_t> bytes;
  struct stat st;
  size_t hint = 0;
  if (::fstat(fd.fd, &st) != 0) return ioError(path, "cannot stat", errno);
  // Devices (/dev/zero, /dev/urandom) never end and directories are no data:
  // only regular files and pipes (/dev/stdin, process substitution) are read.
  if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
    return makeError(path + ": not a regular file (" + fileKind(st.st_mode) + ")");
  if (S_ISREG(st.st_mode) && st.st_size > 0) hint = static_cast<size_t>(st.st_size);
  if (Status s = readAll(fd.fd, path, hint, bytes); !s) return s.error();
  return bytes;
}

Status writeFileAtomic(const std::string& path, const void* data, size_t size) {
  return writeFilesTogether({FileContent{path, data, size}});
}

std::string tempPathFor(const std::string& path) {
  const std::string dir = dirName(path);
  return (path.find('/') == std::string::npos ? std::string() : dir + "/") + "." + baseName(path) +
         kTempInfix + std::to_string(::getpid());
}

Status writeFilesTogether(const std::vector<FileContent>& files) {
  std::vector<std::string> temps;
  for (const FileContent& f : files) {
    temps.push_back(tempPathFor(f.path));
    if (Status st = writeTemp(temps.back(), f.path, f.data, f.size); !st) {
      for (const std::string& t : temps) ::unlink(t.c_str());
      return st;
    }
  }
  std::vector<Backup> backups;
  for (size_t i = 0; i < files.size(); ++i) {
    backups.push_back(keepBackup(files[i].path, temps[i] + "-old"));
    if (::rename(temps[i].c_str(), files[i].path.c_str()) != 0) {
      Status st = ioError(files[i].path, "cannot rename temporary file into place", errno);
      backups.pop_back();
      restoreBackup(files[i].path, temps[i] + "-old");  // rename left the old file as it was
      for (size_t j = i; j-- > 0;) restore(files[j].path, backups[j]);
      for (size_t j = i; j < files.size(); ++j) ::unlink(temps[j].c_str());
      return st;
    }
  }
  for (const Backup& b : backups)
    if (!b.path.empty()) ::unlink(b.path.c_str());
  for (const FileContent& f : files) syncDirectory(f.path);
  return Status();
}

int removeStaleTemps(const std::string& dir, const std::vector<std::string>& names) {
  const std::set<std::string> ours(names.begin(), names.end());
  DIR* d = ::opendir(dir.c_str());
  if (!d) return 0;
  int removed = 0;
  while (dirent* e = ::readdir(d)) {
    const std::string entry = e->d_name;
    long pid = 0;
    if (!tempOwner(entry, ours, &pid)) continue;
    const std::string path = dir + "/" + entry;
    if (processAlive(pid) && !olderThanADay(path)) continue;
    if (::unlink(path.c_str()) == 0) ++removed;
  }
  ::closedir(d);
  return removed;
}

std::string dirName(const std::string& path) {
  size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string baseName(const std::string& path) {
  size_t end = path.find_last_not_of('/');
  if (end == std::string::npos) return path;  // "" or "/"
  size_t slash = path.find_last_of('/', end);
  size_t begin = slash == std::string::npos ? 0 : slash + 1;
  return path.substr(begin, end + 1 - begin);
}

bool hasSuffix(const std::string& path, const std::string& suffix) {
  return path.size() >= suffix.size() &&
         path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace smpl
