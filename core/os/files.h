// The operating system's file primitives, as core/io uses them: one
// implementation per OS (files_posix.cpp: Linux and other POSIX systems;
// files_win32.cpp: Windows, UTF-8 paths converted to UTF-16), chosen by
// core/CMakeLists.txt. Paths are UTF-8 strings. A failed call leaves its
// reason in errorText(), read right after it (errno / GetLastError()).
// Nothing here formats messages for users: callers name the file and what
// they were doing (core/io/file_io.cpp, atomic_write.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace smpl::os {

// The reason the last failed call of this header failed ("No such file or
// directory"), as strerror / FormatMessage give it.
std::string errorText();

enum class FileType { Regular, Directory, Pipe, CharDevice, BlockDevice, Socket, Other };
// "a directory", "a pipe", ...: for "not a regular file (...)" messages.
const char* describe(FileType type);

// A file opened for reading; closed on destruction. Move-only.
class InputFile {
 public:
  InputFile() = default;
  InputFile(InputFile&& other) noexcept;
  InputFile& operator=(InputFile&& other) noexcept;
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile();

  // False on failure (errorText()). `nonblocking`: a FIFO nobody writes to
  // opens without waiting (POSIX O_NONBLOCK; Windows has no FIFOs in paths).
  bool open(const std::string& path, bool nonblocking = false);
  bool isOpen() const { return handle_ != kClosed; }
  // The type and size (bytes; 0 for pipes) of the open file; false on failure.
  bool stat(FileType* type, uint64_t* size) const;
  // Bytes read into buf (at most n; 0 at the end), or -1 on failure. Retries
  // interrupted calls. readAt leaves the file's offset unchanged.
  int64_t read(void* buf, size_t n);
  int64_t readAt(void* buf, size_t n, uint64_t offset);
  void close();

 private:
  static constexpr intptr_t kClosed = -1;
  intptr_t handle_ = kClosed;  // a file descriptor or a HANDLE
};

// A read-only mapping of a whole regular, non-empty file, or nothing (data()
// null: not mappable; the caller reads the file instead). Unmapped on
// destruction. Move-only.
class FileMapping {
 public:
  FileMapping() = default;
  FileMapping(FileMapping&& other) noexcept;
  FileMapping& operator=(FileMapping&& other) noexcept;
  FileMapping(const FileMapping&) = delete;
  FileMapping& operator=(const FileMapping&) = delete;
  ~FileMapping();

  static FileMapping map(const std::string& path);
  const uint8_t* data() const { return data_; }
  size_t size() const { return size_; }
  void unmap();

 private:
  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
};

class Folder;

// A new file created for writing, never an existing name (O_EXCL |
// O_NOFOLLOW; CREATE_NEW), so a planted file or link at the name cannot
// redirect it. While it is open, removeIfUnused() leaves it alone.
class NewFile {
 public:
  enum class Created { Yes, Exists, Failed };
  NewFile() = default;
  NewFile(NewFile&& other) noexcept;
  NewFile& operator=(NewFile&& other) noexcept;
  NewFile(const NewFile&) = delete;
  NewFile& operator=(const NewFile&) = delete;
  ~NewFile();

  Created create(const std::string& path);
  // `name` (one component) in `dir`: openat(2) relative to the folder's handle.
  Created create(const Folder& dir, const std::string& name);
  bool writeAll(const void* data, size_t size);  // false on failure
  bool sync();                                   // to stable storage
  void close();

 private:
  static constexpr intptr_t kClosed = -1;
  intptr_t handle_ = kClosed;
  uint64_t written_ = 0, started_ = 0;  // bytes written; of those, sent to the disk early
};

// A folder opened once; every name below is one component in it, created,
// linked, renamed and removed relative to that handle (openat, linkat,
// renameat, unlinkat; never following a link at the name), so a folder or
// link swapped in on the folder's path after it was opened cannot redirect
// the files written there. The path itself is resolved once, as the user
// gave it. On Windows the folder is held open without FILE_SHARE_DELETE, so
// it cannot be renamed or replaced while held, and names are joined to its
// path. Move-only; closed on destruction.
class Folder {
 public:
  Folder() = default;
  Folder(Folder&& other) noexcept;
  Folder& operator=(Folder&& other) noexcept;
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;
  ~Folder();

  bool open(const std::string& path);  // false on failure (errorText())
  const std::string& path() const { return path_; }
  // "path/name", for messages.
  std::string join(const std::string& name) const;

  bool isFileOrLink(const std::string& name) const;  // a link itself, not its target
  bool exists(const std::string& name) const;
  bool hardLink(const std::string& from, const std::string& to) const;  // a link itself
  bool rename(const std::string& from, const std::string& to) const;    // replaces `to`
  bool remove(const std::string& name) const;
  bool removeIfUnused(const std::string& name) const;  // as os::removeIfUnused
  std::vector<std::string> list() const;               // as os::listFolder
  intptr_t handle() const { return handle_; }

 private:
  static constexpr intptr_t kClosed = -1;
  intptr_t handle_ = kClosed;  // a directory descriptor or a HANDLE
  std::string path_;
};

// Locks on folders that serialise writers of the same folders between
// processes, released when destroyed: `exclusive`, or shared with other shared
// holders (POSIX flock; on Windows every lock is exclusive). Each folder once,
// in a fixed order, so two lockers of the same set never wait crosswise. Best
// effort: a folder that cannot be opened or locked is used unlocked.
class FolderLocks {
 public:
  FolderLocks(const std::vector<std::string>& dirs, bool exclusive);
  // The same for open folders (each locked through a handle of its own).
  FolderLocks(const std::vector<const Folder*>& dirs, bool exclusive);
  ~FolderLocks();
  FolderLocks(const FolderLocks&) = delete;
  FolderLocks& operator=(const FolderLocks&) = delete;
  // Makes renames in the folders durable; best effort.
  void sync() const;

 private:
  std::vector<intptr_t> handles_;
};

// What is at `path` itself (a symbolic link is not followed).
bool isRegularFile(const std::string& path);
bool isFileOrLink(const std::string& path);
bool exists(const std::string& path);
// Identity of the file `path` names (links followed): equal for two paths of
// one file. False if it cannot be examined.
struct FileIdentity {
  uint64_t device = 0, inode = 0;
  FileType type = FileType::Other;
};
bool identify(const std::string& path, FileIdentity* id);

// A second name for the file or link `from` (a link itself, never its target).
bool hardLink(const std::string& from, const std::string& to);
// Renames `from` to `to`, replacing a file at `to`.
bool rename(const std::string& from, const std::string& to);
bool remove(const std::string& path);
// Removes the regular file `path` if no process has it open as a NewFile (its
// writer is gone). A link, a folder or a file that cannot be opened stays.
bool removeIfUnused(const std::string& path);
// The names in folder `dir` (not "." or ".."); empty if it cannot be read.
std::vector<std::string> listFolder(const std::string& dir);

#ifdef _WIN32
// UTF-8 <-> UTF-16, for the wide Win32 API (invalid UTF-8 becomes U+FFFD).
std::wstring widen(const std::string& utf8);
std::string narrow(const std::wstring& utf16);
#endif

}  // namespace smpl::os
