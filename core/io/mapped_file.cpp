#include "core/io/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <utility>

#include "core/io/file_io.h"

namespace smpl {

Result<MappedFile> MappedFile::open(const std::string& path) {
  MappedFile f;
  f.path_ = path;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    // Not MAP_POPULATE: that faults in every page up front, so merely sniffing
    // a 3 GB sparse file cost 3 GB of resident pages; pages are mapped as they
    // are read (no slower for the model loader's full walk, README "Details").
    void* m = ::mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    if (m != MAP_FAILED) {
      f.mapping_ = m;
      f.mapped_size_ = static_cast<size_t>(st.st_size);
      f.guard_ = MappingGuard(m, f.mapped_size_);
      if (!f.guard_.watching()) f.unmap();  // every guard slot taken: read a copy instead
    }
  }
  if (fd >= 0) ::close(fd);
  if (f.mapping_) return f;
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);  // pipes, empty files; refuses devices
  if (!bytes) return bytes.error();
  f.owned_ = std::move(*bytes);
  return f;
}

Status MappedFile::intact() const {
  if (guard_.lost()) return mappingLostError(path_);
  return Status();
}

void MappedFile::unmap() {
  guard_ = MappingGuard();  // stop watching before the range can be reused
  if (mapping_) ::munmap(mapping_, mapped_size_);
  mapping_ = nullptr;
  mapped_size_ = 0;
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    unmap();
    mapping_ = std::exchange(other.mapping_, nullptr);
    mapped_size_ = std::exchange(other.mapped_size_, 0);
    guard_ = std::move(other.guard_);
    path_ = std::move(other.path_);
    owned_ = std::move(other.owned_);
  }
  return *this;
}

MappedFile::~MappedFile() { unmap(); }

}  // namespace smpl
