#include "core/io/mapped_file.h"

#include <utility>

#include "core/io/file_io.h"

namespace smpl {

Result<MappedFile> MappedFile::open(const std::string& path) {
  MappedFile f;
  f.path_ = path;
  f.mapping_ = os::FileMapping::map(path);
  if (f.mapping_.data()) {
    f.guard_ = MappingGuard(f.mapping_.data(), f.mapping_.size());
    if (!f.guard_.watching()) f.unmap();  // every guard slot taken: read a copy instead
  }
  if (f.mapping_.data()) return f;
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
  mapping_.unmap();
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    unmap();
    mapping_ = std::move(other.mapping_);
    guard_ = std::move(other.guard_);
    path_ = std::move(other.path_);
    owned_ = std::move(other.owned_);
  }
  return *this;
}

MappedFile::~MappedFile() { unmap(); }

}  // namespace smpl
