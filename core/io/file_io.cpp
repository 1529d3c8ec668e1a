// Whole-file reads on the OS's open files (core/os/files.h), so that every
// failure can be reported with its reason; the checks of an input's kind
// (sniff, size bound) happen on the open file before its bytes are read.
// Atomic writes are in atomic_write.cpp.
#include "core/io/file_io.h"

#include <algorithm>
#include <cstring>

#include "core/io/printable.h"
#include "core/memory_budget.h"
#include "core/os/files.h"

namespace smpl {
namespace {

Error ioError(const std::string& path, const char* what) {
  return makeError(path + ": " + what + ": " + os::errorText());
}

// An open input with its type and size (bytes; 0 for a pipe).
struct Input {
  os::InputFile file;
  os::FileType type = os::FileType::Other;
  uint64_t size = 0;
  bool regular() const { return type == os::FileType::Regular; }
};

// Reads until EOF into out[used..]; works for regular files, pipes and
// /dev/stdin alike. `hint` (the file size when known) sizes the buffer so a
// regular file is read without regrowing: the +1 leaves room for the read that
// returns EOF. Every buffer size is checked against the memory budget first,
// so an endless pipe ends with an error, not with all of memory; more than
// `max_bytes` in all is refused with `too_large`'s message.
Status readAll(os::InputFile& file, const std::string& path, size_t hint, uint64_t max_bytes,
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
    const int64_t n = file.read(out.data() + used, out.size() - used);
    if (n < 0) return ioError(path, "cannot read");
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  if (used > max_bytes) return makeError(too_large);
  out.resize(used);
  return Status();
}

// Opens `path` for reading and refuses what is not a regular file or a pipe
// (devices never end, directories are no data); pipes also when the kind
// allows none. `probe` (checkInputFile, which never reads a pipe): O_NONBLOCK,
// so opening a FIFO nobody writes to does not hang; a reader waits for its
// writer as open(2) does.
Status openInput(const std::string& path, const InputKind* kind, bool probe, Input* in) {
  if (!in->file.open(path, probe)) return ioError(path, "cannot open");
  if (!in->file.stat(&in->type, &in->size)) return ioError(path, "cannot stat");
  if (!in->regular() && in->type != os::FileType::Pipe)
    return makeError(path + ": not a regular file (" + os::describe(in->type) + ")");
  if (kind && in->type == os::FileType::Pipe && !kind->pipes)
    return makeError(path + ": not a regular file (a pipe); a " + kind->what +
                     " must be a regular file");
  return Status();
}

// The first bytes of an open file (up to kSniffBytes): pread for a regular
// file (the offset stays 0), read for a pipe (those bytes are consumed and
// stay in `head`).
Status readHead(Input& in, const std::string& path, std::vector<uint8_t>* head) {
  head->resize(kSniffBytes);
  size_t used = 0;
  while (used < head->size()) {
    const int64_t n = in.regular() ? in.file.readAt(head->data() + used, head->size() - used, used)
                                   : in.file.read(head->data() + used, head->size() - used);
    if (n < 0) return ioError(path, "cannot read");
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
  Input in;
  if (Status s = openInput(path, nullptr, false, &in); !s) return s.error();
  std::vector<uint8_t> bytes;
  const size_t hint = in.regular() ? static_cast<size_t>(in.size) : 0;
  if (Status s = readAll(in.file, path, hint, ~0ull, "", bytes); !s) return s.error();
  return bytes;
}

Result<std::vector<uint8_t>> readFileBytes(const std::string& path, const InputKind& kind) {
  Input in;
  if (Status s = openInput(path, &kind, false, &in); !s) return s.error();
  std::vector<uint8_t> bytes;
  if (Status s = readHead(in, path, &bytes); !s) return s.error();
  Result<AcceptedFormat> a = matchKind(path, bytes, kind);
  if (!a) return a.error();
  const uint64_t size = in.size;
  if (size > a->max_bytes) return makeError(tooLarge(path, size, kind, *a));
  if (in.regular()) bytes.clear();  // readAt left the offset at 0: read the file from its start
  const std::string too_large = tooLarge(path, size, kind, *a);
  if (Status s = readAll(in.file, path, static_cast<size_t>(size), a->max_bytes, too_large, bytes);
      !s)
    return s.error();
  return bytes;
}

Result<FileFormat> checkInputFile(const std::string& path, const InputKind& kind) {
  Input in;
  if (Status s = openInput(path, &kind, true, &in); !s) return s.error();
  if (!in.regular()) return FileFormat::Unknown;  // a pipe: sniffed by readFileBytes
  std::vector<uint8_t> head;
  if (Status s = readHead(in, path, &head); !s) return s.error();
  Result<AcceptedFormat> a = matchKind(path, head, kind);
  if (!a) return a.error();
  const uint64_t size = in.size;
  if (size > a->max_bytes) return makeError(tooLarge(path, size, kind, *a));
  return a->format;
}

// Path separators: '/' everywhere, and '\\' on Windows (drive letters and
// backslashes: "C:\\out\\body.glb").
#ifdef _WIN32
constexpr const char* kSeparators = "/\\";
#else
constexpr const char* kSeparators = "/";
#endif

std::string dirName(const std::string& path) {
  size_t slash = path.find_last_of(kSeparators);
  if (slash == std::string::npos) return ".";
#ifdef _WIN32
  if (slash == 2 && path[1] == ':') return path.substr(0, 3);  // "C:\\x" -> "C:\\"
#endif
  return slash == 0 ? path.substr(0, 1) : path.substr(0, slash);
}

std::string baseName(const std::string& path) {
  size_t end = path.find_last_not_of(kSeparators);
  if (end == std::string::npos) return path;  // "" or "/"
  size_t slash = path.find_last_of(kSeparators, end);
  size_t begin = slash == std::string::npos ? 0 : slash + 1;
  return path.substr(begin, end + 1 - begin);
}

bool hasSuffix(const std::string& path, const std::string& suffix) {
  return path.size() >= suffix.size() &&
         path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace smpl
