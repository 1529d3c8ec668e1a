// Windows implementation of core/os/files.h: UTF-8 paths converted to UTF-16
// for the wide Win32 API (CreateFileW ...). A NewFile is created with
// CREATE_NEW (fails on any existing name, a link included) and opened so that
// it can be renamed while open but not opened by anyone wanting exclusive
// access: removeIfUnused opens with no sharing, which fails while its writer
// holds it (that is how a live temporary is told from a stale one). Folder
// locks are named mutexes, one per folder's full path (exclusive only; a
// mutex whose holder died is taken over, WAIT_ABANDONED).
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>

#include <algorithm>
#include <cwchar>
#include <utility>

#include "core/os/files.h"

namespace smpl::os {
namespace {

thread_local DWORD t_error = 0;

bool fail() {
  t_error = GetLastError();
  return false;
}

HANDLE asHandle(intptr_t h) { return reinterpret_cast<HANDLE>(h); }

}  // namespace

// UTF-8 -> UTF-16 (invalid sequences become U+FFFD, as Windows does).
std::wstring widen(const std::string& s) {
  if (s.empty()) return std::wstring();
  const int n = MultiByteToWideChar(CP_UTF8, 0, s.data(), static_cast<int>(s.size()), nullptr, 0);
  std::wstring w(static_cast<size_t>(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, s.data(), static_cast<int>(s.size()), w.data(), n);
  return w;
}

std::string narrow(const std::wstring& w) {
  if (w.empty()) return std::string();
  const int n = WideCharToMultiByte(CP_UTF8, 0, w.data(), static_cast<int>(w.size()), nullptr, 0,
                                    nullptr, nullptr);
  std::string s(static_cast<size_t>(n), '\0');
  WideCharToMultiByte(CP_UTF8, 0, w.data(), static_cast<int>(w.size()), s.data(), n, nullptr,
                      nullptr);
  return s;
}

std::string errorText() {
  wchar_t* text = nullptr;
  const DWORD n = FormatMessageW(
      FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
      nullptr, t_error, MAKELANGID(LANG_ENGLISH, SUBLANG_ENGLISH_US),
      reinterpret_cast<wchar_t*>(&text), 0, nullptr);
  std::wstring w = n > 0 && text ? std::wstring(text, n) : std::wstring();
  if (text) LocalFree(text);
  while (!w.empty() && (w.back() == L'\n' || w.back() == L'\r' || w.back() == L'.')) w.pop_back();
  return w.empty() ? "error " + std::to_string(t_error) : narrow(w);
}

const char* describe(FileType type) {
  switch (type) {
    case FileType::Directory:
      return "a directory";
    case FileType::CharDevice:
      return "a character device";
    case FileType::Pipe:
      return "a pipe";
    default:
      return "not a file";
  }
}

namespace {

FileType typeOfHandle(HANDLE h) {
  switch (GetFileType(h)) {
    case FILE_TYPE_CHAR:
      return FileType::CharDevice;
    case FILE_TYPE_PIPE:
      return FileType::Pipe;
    case FILE_TYPE_DISK:
      break;
    default:
      return FileType::Other;
  }
  BY_HANDLE_FILE_INFORMATION info{};
  if (!GetFileInformationByHandle(h, &info)) return FileType::Other;
  return (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY) ? FileType::Directory
                                                            : FileType::Regular;
}

// Opens `path` for reading (folders too: FILE_FLAG_BACKUP_SEMANTICS), sharing
// read, write and delete so a reader never blocks a writer.
HANDLE openRead(const std::string& path, DWORD flags = 0) {
  return CreateFileW(widen(path).c_str(), GENERIC_READ,
                     FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, nullptr, OPEN_EXISTING,
                     FILE_ATTRIBUTE_NORMAL | FILE_FLAG_BACKUP_SEMANTICS | flags, nullptr);
}

DWORD attributesOf(const std::string& path) { return GetFileAttributesW(widen(path).c_str()); }

}  // namespace

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

bool InputFile::open(const std::string& path, bool) {
  close();
  HANDLE h = openRead(path);
  if (h == INVALID_HANDLE_VALUE) return fail();
  handle_ = reinterpret_cast<intptr_t>(h);
  return true;
}

bool InputFile::stat(FileType* type, uint64_t* size) const {
  *type = typeOfHandle(asHandle(handle_));
  *size = 0;
  LARGE_INTEGER n{};
  if (*type == FileType::Regular) {
    if (!GetFileSizeEx(asHandle(handle_), &n)) return fail();
    *size = static_cast<uint64_t>(n.QuadPart);
  }
  return true;
}

int64_t InputFile::read(void* buf, size_t n) {
  DWORD got = 0;
  const DWORD want = static_cast<DWORD>(std::min<size_t>(n, 1u << 30));
  if (!ReadFile(asHandle(handle_), buf, want, &got, nullptr)) {
    if (GetLastError() == ERROR_BROKEN_PIPE) return 0;  // the writer closed its end
    fail();
    return -1;
  }
  return got;
}

int64_t InputFile::readAt(void* buf, size_t n, uint64_t offset) {
  // ReadFile with an OVERLAPPED offset on a synchronous handle moves the
  // file pointer; put it back so readAt leaves the offset unchanged.
  LARGE_INTEGER zero{}, here{};
  if (!SetFilePointerEx(asHandle(handle_), zero, &here, FILE_CURRENT)) {
    fail();
    return -1;
  }
  OVERLAPPED at{};
  at.Offset = static_cast<DWORD>(offset);
  at.OffsetHigh = static_cast<DWORD>(offset >> 32);
  DWORD got = 0;
  const DWORD want = static_cast<DWORD>(std::min<size_t>(n, 1u << 30));
  const bool ok = ReadFile(asHandle(handle_), buf, want, &got, &at) != 0;
  const DWORD err = GetLastError();
  SetFilePointerEx(asHandle(handle_), here, nullptr, FILE_BEGIN);
  if (!ok && err == ERROR_HANDLE_EOF) return 0;
  if (!ok) {
    t_error = err;
    return -1;
  }
  return got;
}

void InputFile::close() {
  if (handle_ != kClosed) CloseHandle(asHandle(handle_));
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

// While the view exists, Windows refuses to truncate the file (SetEndOfFile:
// ERROR_USER_MAPPED_FILE), so the mapping cannot shrink under its reader.
FileMapping FileMapping::map(const std::string& path) {
  FileMapping m;
  HANDLE file = openRead(path);
  if (file == INVALID_HANDLE_VALUE) return m;
  LARGE_INTEGER size{};
  if (typeOfHandle(file) == FileType::Regular && GetFileSizeEx(file, &size) && size.QuadPart > 0) {
    HANDLE section = CreateFileMappingW(file, nullptr, PAGE_READONLY, 0, 0, nullptr);
    if (section) {
      const void* p = MapViewOfFile(section, FILE_MAP_READ, 0, 0, 0);
      if (p) {
        m.data_ = static_cast<const uint8_t*>(p);
        m.size_ = static_cast<size_t>(size.QuadPart);
      }
      CloseHandle(section);  // the view keeps the section alive
    }
  }
  CloseHandle(file);
  return m;
}

void FileMapping::unmap() {
  if (data_) UnmapViewOfFile(data_);
  data_ = nullptr;
  size_ = 0;
}

// ---- NewFile

NewFile::NewFile(NewFile&& other) noexcept : handle_(std::exchange(other.handle_, kClosed)) {}

NewFile& NewFile::operator=(NewFile&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = std::exchange(other.handle_, kClosed);
  }
  return *this;
}

NewFile::~NewFile() { close(); }

NewFile::Created NewFile::create(const std::string& path) {
  close();
  HANDLE h = CreateFileW(widen(path).c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_DELETE,
                         nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr);
  if (h == INVALID_HANDLE_VALUE) {
    fail();
    return t_error == ERROR_FILE_EXISTS || t_error == ERROR_ALREADY_EXISTS ? Created::Exists
                                                                           : Created::Failed;
  }
  handle_ = reinterpret_cast<intptr_t>(h);
  return Created::Yes;
}

bool NewFile::writeAll(const void* data, size_t size) {
  const auto* p = static_cast<const uint8_t*>(data);
  while (size > 0) {
    DWORD put = 0;
    const DWORD want = static_cast<DWORD>(std::min<size_t>(size, 1u << 30));
    if (!WriteFile(asHandle(handle_), p, want, &put, nullptr)) return fail();
    p += put;
    size -= put;
  }
  return true;
}

bool NewFile::sync() { return FlushFileBuffers(asHandle(handle_)) != 0 || fail(); }

void NewFile::close() {
  if (handle_ != kClosed) CloseHandle(asHandle(handle_));
  handle_ = kClosed;
}

NewFile::Created NewFile::create(const Folder& dir, const std::string& name) {
  return create(dir.join(name));
}

// ---- Folder: held open without FILE_SHARE_DELETE (nobody can rename or
// remove it meanwhile); names joined to its path.

Folder::Folder(Folder&& other) noexcept
    : handle_(std::exchange(other.handle_, kClosed)), path_(std::move(other.path_)) {}

Folder& Folder::operator=(Folder&& other) noexcept {
  if (this != &other) {
    if (handle_ != kClosed) CloseHandle(asHandle(handle_));
    handle_ = std::exchange(other.handle_, kClosed);
    path_ = std::move(other.path_);
  }
  return *this;
}

Folder::~Folder() {
  if (handle_ != kClosed) CloseHandle(asHandle(handle_));
}

bool Folder::open(const std::string& path) {
  if (handle_ != kClosed) CloseHandle(asHandle(handle_));
  handle_ = kClosed;
  path_ = path;
  HANDLE h = CreateFileW(widen(path.empty() ? "." : path).c_str(), FILE_LIST_DIRECTORY,
                         FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr, OPEN_EXISTING,
                         FILE_FLAG_BACKUP_SEMANTICS, nullptr);
  if (h == INVALID_HANDLE_VALUE) return fail();
  handle_ = reinterpret_cast<intptr_t>(h);
  return true;
}

std::string Folder::join(const std::string& name) const {
  if (path_.empty() || path_ == ".") return name;
  const char last = path_.back();
  return path_ + (last == '/' || last == '\\' ? "" : "\\") + name;
}

bool Folder::isFileOrLink(const std::string& name) const { return os::isFileOrLink(join(name)); }
bool Folder::exists(const std::string& name) const { return os::exists(join(name)); }
bool Folder::hardLink(const std::string& from, const std::string& to) const {
  return os::hardLink(join(from), join(to));
}
bool Folder::rename(const std::string& from, const std::string& to) const {
  return os::rename(join(from), join(to));
}
bool Folder::remove(const std::string& name) const { return os::remove(join(name)); }
bool Folder::removeIfUnused(const std::string& name) const {
  return os::removeIfUnused(join(name));
}
std::vector<std::string> Folder::list() const { return listFolder(path_); }

// ---- FolderLocks

namespace {

// The folder's full path, case-folded (NTFS names are case-insensitive), with
// no trailing separator: the same key for every spelling of one folder.
std::wstring folderKey(const std::string& dir) {
  const std::wstring w = widen(dir.empty() ? "." : dir);
  wchar_t full[32768];
  const DWORD n = GetFullPathNameW(w.c_str(), 32768, full, nullptr);
  std::wstring key = n > 0 && n < 32768 ? std::wstring(full, n) : w;
  for (wchar_t& c : key) c = c == L'/' ? L'\\' : static_cast<wchar_t>(towlower(c));
  while (key.size() > 3 && key.back() == L'\\') key.pop_back();
  return key;
}

// A mutex name may not hold backslashes and is at most MAX_PATH: the key's hash.
std::wstring mutexName(const std::wstring& key) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (wchar_t c : key) h = (h ^ static_cast<uint16_t>(c)) * 1099511628211ull;
  wchar_t name[64];
  swprintf(name, 64, L"Local\\smpl-export-folder-%016llx", static_cast<unsigned long long>(h));
  return name;
}

}  // namespace

FolderLocks::FolderLocks(const std::vector<std::string>& dirs, bool) {
  std::vector<std::wstring> names;
  for (const std::string& dir : dirs) names.push_back(mutexName(folderKey(dir)));
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  for (const std::wstring& name : names) {
    HANDLE m = CreateMutexW(nullptr, FALSE, name.c_str());
    if (!m) continue;
    const DWORD r = WaitForSingleObject(m, INFINITE);
    if (r != WAIT_OBJECT_0 && r != WAIT_ABANDONED) {
      CloseHandle(m);
      continue;
    }
    handles_.push_back(reinterpret_cast<intptr_t>(m));
  }
}

namespace {

std::vector<std::string> pathsOf(const std::vector<const Folder*>& dirs) {
  std::vector<std::string> paths;
  for (const Folder* dir : dirs) paths.push_back(dir->path());
  return paths;
}

}  // namespace

FolderLocks::FolderLocks(const std::vector<const Folder*>& dirs, bool exclusive)
    : FolderLocks(pathsOf(dirs), exclusive) {}

FolderLocks::~FolderLocks() {
  for (auto it = handles_.rbegin(); it != handles_.rend(); ++it) {
    ReleaseMutex(asHandle(*it));
    CloseHandle(asHandle(*it));
  }
}

void FolderLocks::sync() const {}  // NTFS journals renames; files were flushed

// ---- paths

bool isRegularFile(const std::string& path) {
  const DWORD a = attributesOf(path);
  return a != INVALID_FILE_ATTRIBUTES &&
         !(a & (FILE_ATTRIBUTE_DIRECTORY | FILE_ATTRIBUTE_REPARSE_POINT | FILE_ATTRIBUTE_DEVICE));
}

bool isFileOrLink(const std::string& path) {
  const DWORD a = attributesOf(path);
  if (a == INVALID_FILE_ATTRIBUTES) return false;
  return (a & FILE_ATTRIBUTE_REPARSE_POINT) || !(a & FILE_ATTRIBUTE_DIRECTORY);
}

bool exists(const std::string& path) { return attributesOf(path) != INVALID_FILE_ATTRIBUTES; }

bool identify(const std::string& path, FileIdentity* id) {
  if (path.empty()) return false;
  HANDLE h = openRead(path);
  if (h == INVALID_HANDLE_VALUE) return fail();
  BY_HANDLE_FILE_INFORMATION info{};
  const bool ok = GetFileInformationByHandle(h, &info) != 0 || fail();
  if (ok) {
    *id = FileIdentity{info.dwVolumeSerialNumber,
                       (static_cast<uint64_t>(info.nFileIndexHigh) << 32) | info.nFileIndexLow,
                       typeOfHandle(h)};
  }
  CloseHandle(h);
  return ok;
}

bool hardLink(const std::string& from, const std::string& to) {
  return CreateHardLinkW(widen(to).c_str(), widen(from).c_str(), nullptr) != 0 || fail();
}

bool rename(const std::string& from, const std::string& to) {
  return MoveFileExW(widen(from).c_str(), widen(to).c_str(),
                     MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) != 0 ||
         fail();
}

bool remove(const std::string& path) { return DeleteFileW(widen(path).c_str()) != 0 || fail(); }

// No sharing: fails (ERROR_SHARING_VIOLATION) while a NewFile holds it.
// FILE_FLAG_OPEN_REPARSE_POINT: a link is opened itself, and then left alone.
bool removeIfUnused(const std::string& path) {
  if (!isRegularFile(path)) return false;
  HANDLE h = CreateFileW(widen(path).c_str(), DELETE, 0, nullptr, OPEN_EXISTING,
                         FILE_FLAG_DELETE_ON_CLOSE | FILE_FLAG_OPEN_REPARSE_POINT, nullptr);
  if (h == INVALID_HANDLE_VALUE) return false;
  CloseHandle(h);  // deletes it
  return true;
}

std::vector<std::string> listFolder(const std::string& dir) {
  std::vector<std::string> names;
  WIN32_FIND_DATAW entry;
  HANDLE find = FindFirstFileW(widen(dir + "\\*").c_str(), &entry);
  if (find == INVALID_HANDLE_VALUE) return names;
  do {
    const std::wstring name = entry.cFileName;
    if (name != L"." && name != L"..") names.push_back(narrow(name));
  } while (FindNextFileW(find, &entry));
  FindClose(find);
  return names;
}

}  // namespace smpl::os
