// POSIX implementation of core/os/files.h: file descriptors, mmap(2),
// O_EXCL | O_NOFOLLOW creation held by an flock(2) while its writer lives
// (how removeIfUnused tells a live temporary from a stale one, never by pid),
// flocks on folders.
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "core/os/files.h"

namespace smpl::os {
namespace {

thread_local int t_error = 0;

bool fail() {
  t_error = errno;
  return false;
}

int flockRetry(int fd, int operation) {
  int r;
  while ((r = ::flock(fd, operation)) != 0 && errno == EINTR) {
  }
  return r;
}

FileType typeOf(mode_t mode) {
  if (S_ISREG(mode)) return FileType::Regular;
  if (S_ISDIR(mode)) return FileType::Directory;
  if (S_ISFIFO(mode)) return FileType::Pipe;
  if (S_ISCHR(mode)) return FileType::CharDevice;
  if (S_ISBLK(mode)) return FileType::BlockDevice;
  if (S_ISSOCK(mode)) return FileType::Socket;
  return FileType::Other;
}

int64_t retry(ssize_t (*call)(int, void*, size_t, off_t), int fd, void* buf, size_t n,
              uint64_t offset) {
  for (;;) {
    const ssize_t r = call(fd, buf, n, static_cast<off_t>(offset));
    if (r >= 0) return r;
    if (errno != EINTR) {
      t_error = errno;
      return -1;
    }
  }
}

ssize_t readNoOffset(int fd, void* buf, size_t n, off_t) { return ::read(fd, buf, n); }

}  // namespace

std::string errorText() { return std::strerror(t_error); }

const char* describe(FileType type) {
  switch (type) {
    case FileType::Directory:
      return "a directory";
    case FileType::CharDevice:
      return "a character device";
    case FileType::BlockDevice:
      return "a block device";
    case FileType::Socket:
      return "a socket";
    case FileType::Pipe:
      return "a pipe";
    default:
      return "not a file";
  }
}

// ---- InputFile

InputFile::InputFile(InputFile&& other) noexcept : handle_(std::exchange(other.handle_, kClosed)) {}

InputFile& InputFile::operator=(InputFile&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = std::exchange(other.handle_, kClosed);
  }
  return *this;
}

InputFile::~InputFile() { close(); }

bool InputFile::open(const std::string& path, bool nonblocking) {
  close();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (nonblocking ? O_NONBLOCK : 0));
  if (fd < 0) return fail();
  handle_ = fd;
  return true;
}

bool InputFile::stat(FileType* type, uint64_t* size) const {
  struct stat st {};
  if (::fstat(static_cast<int>(handle_), &st) != 0) return fail();
  *type = typeOf(st.st_mode);
  *size = S_ISREG(st.st_mode) ? static_cast<uint64_t>(st.st_size) : 0;
  return true;
}

int64_t InputFile::read(void* buf, size_t n) {
  return retry(readNoOffset, static_cast<int>(handle_), buf, n, 0);
}

int64_t InputFile::readAt(void* buf, size_t n, uint64_t offset) {
  return retry(::pread, static_cast<int>(handle_), buf, n, offset);
}

void InputFile::close() {
  if (handle_ != kClosed) ::close(static_cast<int>(handle_));
  handle_ = kClosed;
}

// ---- FileMapping

FileMapping::FileMapping(FileMapping&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

FileMapping& FileMapping::operator=(FileMapping&& other) noexcept {
  if (this != &other) {
    unmap();
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

FileMapping::~FileMapping() { unmap(); }

// Not MAP_POPULATE: that faults in every page up front, so merely sniffing
// a 3 GB sparse file cost 3 GB of resident pages; pages are mapped as they
// are read (no slower for the model loader's full walk, README "Details").
FileMapping FileMapping::map(const std::string& path) {
  FileMapping m;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    void* p = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (p != MAP_FAILED) {
      m.data_ = static_cast<const uint8_t*>(p);
      m.size_ = static_cast<size_t>(st.st_size);
    }
  }
  if (fd >= 0) ::close(fd);
  return m;
}

void FileMapping::unmap() {
  if (data_) ::munmap(const_cast<uint8_t*>(data_), size_);
  data_ = nullptr;
  size_ = 0;
}

// ---- NewFile

NewFile::NewFile(NewFile&& other) noexcept
    : handle_(std::exchange(other.handle_, kClosed)),
      written_(other.written_),
      started_(other.started_) {}

NewFile& NewFile::operator=(NewFile&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = std::exchange(other.handle_, kClosed);
    written_ = other.written_;
    started_ = other.started_;
  }
  return *this;
}

NewFile::~NewFile() { close(); }

namespace {

// O_EXCL | O_NOFOLLOW relative to `dir` (AT_FDCWD: the working folder).
NewFile::Created createAt(int dir, const std::string& name, intptr_t* handle) {
  const int fd =
      ::openat(dir, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) {
    t_error = errno;
    return errno == EEXIST ? NewFile::Created::Exists : NewFile::Created::Failed;
  }
  flockRetry(fd, LOCK_EX | LOCK_NB);  // a new inode: nobody else can hold it
  *handle = fd;
  return NewFile::Created::Yes;
}

}  // namespace

NewFile::Created NewFile::create(const std::string& path) {
  close();
  written_ = started_ = 0;
  return createAt(AT_FDCWD, path, &handle_);
}

bool NewFile::writeAll(const void* data, size_t size) {
  const auto* p = static_cast<const uint8_t*>(data);
  while (size > 0) {
    ssize_t n = ::write(static_cast<int>(handle_), p, std::min<size_t>(size, 1u << 30));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return fail();
    p += n;
    size -= static_cast<size_t>(n);
    written_ += uint64_t(n);
  }
#ifdef __linux__
  // Start the disk writes of every 4 MB while the rest is written, so that
  // sync() waits for the last part only.
  if (written_ - started_ >= (4u << 20)) {
    ::sync_file_range(static_cast<int>(handle_), off64_t(started_), off64_t(written_ - started_),
                      SYNC_FILE_RANGE_WRITE);
    started_ = written_;
  }
#endif
  return true;
}

bool NewFile::sync() { return ::fsync(static_cast<int>(handle_)) == 0 || fail(); }

void NewFile::close() {
  if (handle_ != kClosed) ::close(static_cast<int>(handle_));  // closing releases the flock
  handle_ = kClosed;
}

NewFile::Created NewFile::create(const Folder& dir, const std::string& name) {
  close();
  written_ = started_ = 0;
  return createAt(static_cast<int>(dir.handle()), name, &handle_);
}

// ---- Folder

Folder::Folder(Folder&& other) noexcept
    : handle_(std::exchange(other.handle_, kClosed)), path_(std::move(other.path_)) {}

Folder& Folder::operator=(Folder&& other) noexcept {
  if (this != &other) {
    if (handle_ != kClosed) ::close(static_cast<int>(handle_));
    handle_ = std::exchange(other.handle_, kClosed);
    path_ = std::move(other.path_);
  }
  return *this;
}

Folder::~Folder() {
  if (handle_ != kClosed) ::close(static_cast<int>(handle_));
}

bool Folder::open(const std::string& path) {
  if (handle_ != kClosed) ::close(static_cast<int>(handle_));
  handle_ = kClosed;
  path_ = path;
  const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return fail();
  handle_ = fd;
  return true;
}

std::string Folder::join(const std::string& name) const {
  if (path_.empty() || path_ == ".") return name;
  return path_ + (path_.back() == '/' ? "" : "/") + name;
}

bool Folder::isFileOrLink(const std::string& name) const {
  struct stat st {};
  return ::fstatat(static_cast<int>(handle_), name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 &&
         (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode));
}

bool Folder::exists(const std::string& name) const {
  struct stat st {};
  return ::fstatat(static_cast<int>(handle_), name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0;
}

bool Folder::hardLink(const std::string& from, const std::string& to) const {
  const int fd = static_cast<int>(handle_);
  return ::linkat(fd, from.c_str(), fd, to.c_str(), 0) == 0 || fail();
}

bool Folder::rename(const std::string& from, const std::string& to) const {
  const int fd = static_cast<int>(handle_);
  return ::renameat(fd, from.c_str(), fd, to.c_str()) == 0 || fail();
}

bool Folder::remove(const std::string& name) const {
  return ::unlinkat(static_cast<int>(handle_), name.c_str(), 0) == 0 || fail();
}

bool Folder::removeIfUnused(const std::string& name) const {
  const int dir = static_cast<int>(handle_);
  struct stat before {
  }, now{};
  if (::fstatat(dir, name.c_str(), &before, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(before.st_mode))
    return false;
  const int fd = ::openat(dir, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  bool removed = false;
  if (::fstat(fd, &now) == 0 && now.st_dev == before.st_dev && now.st_ino == before.st_ino &&
      flockRetry(fd, LOCK_EX | LOCK_NB) == 0)
    removed = ::unlinkat(dir, name.c_str(), 0) == 0;
  ::close(fd);
  return removed;
}

std::vector<std::string> Folder::list() const {
  std::vector<std::string> names;
  const int fd = ::openat(static_cast<int>(handle_), ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return names;
  DIR* d = ::fdopendir(fd);
  if (!d) {
    ::close(fd);
    return names;
  }
  while (dirent* e = ::readdir(d)) {
    const std::string entry = e->d_name;
    if (entry != "." && entry != "..") names.push_back(entry);
  }
  ::closedir(d);  // closes fd
  return names;
}

// ---- FolderLocks

namespace {

// Locks the open folder descriptors `fds` (taken over), once per folder, in
// (device, inode) order.
std::vector<intptr_t> lockFolders(const std::vector<int>& fds, bool exclusive) {
  std::vector<std::pair<std::pair<dev_t, ino_t>, int>> open;
  for (const int fd : fds) {
    struct stat st {};
    if (fd < 0) continue;
    if (::fstat(fd, &st) != 0) {
      ::close(fd);
      continue;
    }
    open.push_back({{st.st_dev, st.st_ino}, fd});
  }
  std::sort(open.begin(), open.end());
  std::vector<intptr_t> handles;
  for (size_t i = 0; i < open.size(); ++i) {
    if (i > 0 && open[i].first == open[i - 1].first) {
      ::close(open[i].second);  // the same folder by another path: one lock is enough
      continue;
    }
    flockRetry(open[i].second, exclusive ? LOCK_EX : LOCK_SH);
    handles.push_back(open[i].second);
  }
  return handles;
}

}  // namespace

FolderLocks::FolderLocks(const std::vector<std::string>& dirs, bool exclusive) {
  std::vector<int> fds;
  for (const std::string& dir : dirs)
    fds.push_back(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  handles_ = lockFolders(fds, exclusive);
}

// A new open file description per folder ("." relative to its handle): an
// flock belongs to the description, so the lock ends with this object, not
// with the Folder.
FolderLocks::FolderLocks(const std::vector<const Folder*>& dirs, bool exclusive) {
  std::vector<int> fds;
  for (const Folder* dir : dirs)
    fds.push_back(
        ::openat(static_cast<int>(dir->handle()), ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  handles_ = lockFolders(fds, exclusive);
}

FolderLocks::~FolderLocks() {
  for (intptr_t fd : handles_) ::close(static_cast<int>(fd));  // closing releases the flock
}

void FolderLocks::sync() const {
  for (intptr_t fd : handles_) ::fsync(static_cast<int>(fd));
}

// ---- paths

bool isRegularFile(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

bool isFileOrLink(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0 && (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode));
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0;
}

bool identify(const std::string& path, FileIdentity* id) {
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return fail();  // follows symlinks
  *id = FileIdentity{static_cast<uint64_t>(st.st_dev), static_cast<uint64_t>(st.st_ino),
                     typeOf(st.st_mode)};
  return true;
}

// linkat without AT_SYMLINK_FOLLOW links a symbolic link itself, never its target.
bool hardLink(const std::string& from, const std::string& to) {
  return ::linkat(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), 0) == 0 || fail();
}

bool rename(const std::string& from, const std::string& to) {
  return ::rename(from.c_str(), to.c_str()) == 0 || fail();
}

bool remove(const std::string& path) { return ::unlink(path.c_str()) == 0 || fail(); }

bool removeIfUnused(const std::string& path) {
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

std::vector<std::string> listFolder(const std::string& dir) {
  std::vector<std::string> names;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return names;
  while (dirent* e = ::readdir(d)) {
    const std::string entry = e->d_name;
    if (entry != "." && entry != "..") names.push_back(entry);
  }
  ::closedir(d);
  return names;
}

}  // namespace smpl::os
