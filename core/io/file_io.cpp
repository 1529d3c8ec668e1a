// Whole-file reads on POSIX file descriptors, so that every failure can be
// reported with strerror; the checks of an input's kind (sniff, size bound)
// happen on the open descriptor before its bytes are read. Atomic writes are
// in atomic_write.cpp.
#include "core/io/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/io/printable.h"
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

// Reads until EOF into out[used..]; works for regular files, pipes and
// /dev/stdin alike. `hint` (the file size when known) sizes the buffer so a
// regular file is read without regrowing: the +1 leaves room for the read that
// returns EOF. Every buffer size is checked against the memory budget first,
// so an endless pipe ends with an error, not with all of memory; more than
// `max_bytes` in all is refused with `too_large`'s message.
Status readAll(int fd, const std::string& path, size_t hint, uint64_t max_bytes,
               const std::string& too_large, std::vector<uint8_t>& out) {
  size_t used = out.size();
  const size_t first = std::max<size_t>(std::max<size_t>(hint + 1, 65536), used);
  if (Status st = checkMemory(first, path, "reading the file"); !st) return st;
  out.resize(first);
  for (;;) {
    if (used == out.size()) {
      if (used > max_bytes) return makeError(too_large);
      if (Status st = checkMemory(out.size() * 2, path, "reading the file"); !st) return st;
      out.resize(out.size() * 2);
    }
    ssize_t n = ::read(fd, out.data() + used, out.size() - used);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return ioError(path, "cannot read", errno);
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  if (used > max_bytes) return makeError(too_large);
  out.resize(used);
  return Status();
}

const char* fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISFIFO(mode)) return "a pipe";
  return "not a file";
}

// Opens `path` for reading and refuses what is not a regular file or a pipe
// (devices never end, directories are no data); pipes also when the kind
// allows none. `probe` (checkInputFile, which never reads a pipe): O_NONBLOCK,
// so opening a FIFO nobody writes to does not hang; a reader waits for its
// writer as open(2) does.
Status openInput(const std::string& path, const InputKind* kind, bool probe, Fd* fd,
                 struct stat* st) {
  fd->fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (probe ? O_NONBLOCK : 0));
  if (fd->fd < 0) return ioError(path, "cannot open", errno);
  if (::fstat(fd->fd, st) != 0) return ioError(path, "cannot stat", errno);
  if (!S_ISREG(st->st_mode) && !S_ISFIFO(st->st_mode))
    return makeError(path + ": not a regular file (" + fileKind(st->st_mode) + ")");
  if (kind && S_ISFIFO(st->st_mode) && !kind->pipes)
    return makeError(path + ": not a regular file (a pipe); a " + kind->what +
                     " must be a regular file");
  return Status();
}

// The first bytes of an open file (up to kSniffBytes): pread for a regular
// file (the offset stays 0), read for a pipe (those bytes are consumed and
// stay in `head`).
Status readHead(int fd, bool regular, const std::string& path, std::vector<uint8_t>* head) {
  head->resize(kSniffBytes);
  size_t used = 0;
  while (used < head->size()) {
    ssize_t n = regular ? ::pread(fd, head->data() + used, head->size() - used, used)
                        : ::read(fd, head->data() + used, head->size() - used);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return ioError(path, "cannot read", errno);
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  head->resize(used);
  return Status();
}

std::string expectedFormats(const InputKind& kind) {
  std::string list;
  for (size_t i = 0; i < kind.formats.size(); ++i)
    list += std::string(i == 0                         ? ""
                        : i + 1 == kind.formats.size() ? " or "
                                                       : ", ") +
            formatName(kind.formats[i].format);
  return list;
}

// `size`: the regular file's size, or 0 for a pipe that gave more than the bound.
std::string tooLarge(const std::string& path, uint64_t size, const InputKind& kind,
                     const AcceptedFormat& a) {
  return path + ": " + (size > 0 ? formatBytes(size) : "more than that from a pipe") +
         " is too large for a " + kind.what + " in " + formatName(a.format) + " (at most " +
         formatBytes(a.max_bytes) + ")";
}

// The format `head` shows with the kind's bound for it, or the one-line refusal.
Result<AcceptedFormat> matchKind(const std::string& path, const std::vector<uint8_t>& head,
                                 const InputKind& kind) {
  if (head.empty())
    return makeError(path + ": empty file; expected a " + kind.what + " (" + expectedFormats(kind) +
                     ")");
  const FileFormat f = sniffFormat(head.data(), head.size());
  if (const AcceptedFormat* a = acceptedFormat(kind, f)) return AcceptedFormat{f, a->max_bytes};
  std::string start;
  for (size_t i = 0; i < std::min<size_t>(head.size(), 8); ++i) start += static_cast<char>(head[i]);
  return makeError(path + ": not a " + kind.what + " (expected " + expectedFormats(kind) +
                   "; the file starts with '" + printable(start, 64) + "'" +
                   (f == FileFormat::Unknown ? "" : std::string(", ") + formatName(f)) + ")");
}

}  // namespace

Result<std::vector<uint8_t>> readFileBytes(const std::string& path) {
  Fd fd(-1);
  struct stat st {};
  if (Status s = openInput(path, nullptr, false, &fd, &st); !s) return s.error();
  std::vector<uint8_t> bytes;
  const size_t hint = S_ISREG(st.st_mode) && st.st_size > 0 ? static_cast<size_t>(st.st_size) : 0;
  if (Status s = readAll(fd.fd, path, hint, ~0ull, "", bytes); !s) return s.error();
  return bytes;
}

Result<std::vector<uint8_t>> readFileBytes(const std::string& path, const InputKind& kind) {
  Fd fd(-1);
  struct stat st {};
  if (Status s = openInput(path, &kind, false, &fd, &st); !s) return s.error();
  const bool regular = S_ISREG(st.st_mode);
  std::vector<uint8_t> bytes;
  if (Status s = readHead(fd.fd, regular, path, &bytes); !s) return s.error();
  Result<AcceptedFormat> a = matchKind(path, bytes, kind);
  if (!a) return a.error();
  const uint64_t size = regular ? static_cast<uint64_t>(st.st_size) : 0;
  if (size > a->max_bytes) return makeError(tooLarge(path, size, kind, *a));
  if (regular) bytes.clear();  // pread left the offset at 0: read the file from its start
  const std::string too_large = tooLarge(path, size, kind, *a);
  if (Status s = readAll(fd.fd, path, static_cast<size_t>(size), a->max_bytes, too_large, bytes);
      !s)
    return s.error();
  return bytes;
}

Result<FileFormat> checkInputFile(const std::string& path, const InputKind& kind) {
  Fd fd(-1);
  struct stat st {};
  if (Status s = openInput(path, &kind, true, &fd, &st); !s) return s.error();
  if (!S_ISREG(st.st_mode)) return FileFormat::Unknown;  // a pipe: sniffed by readFileBytes
  std::vector<uint8_t> head;
  if (Status s = readHead(fd.fd, true, path, &head); !s) return s.error();
  Result<AcceptedFormat> a = matchKind(path, head, kind);
  if (!a) return a.error();
  const uint64_t size = static_cast<uint64_t>(st.st_size);
  if (size > a->max_bytes) return makeError(tooLarge(path, size, kind, *a));
  return a->format;
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
