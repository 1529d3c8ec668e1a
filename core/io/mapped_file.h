// A whole input file's bytes without copying them: a read-only private
// mapping of a regular file (the pages come straight from the page cache,
// all mapped in one call since the reader walks every byte), or, for what
// cannot be mapped (pipes, empty files), readFileBytes' copy with its checks
// (devices refused, memory budget).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

class MappedFile {
 public:
  // Errors as readFileBytes: "<path>: cannot open", "<path>: not a regular file ...".
  static Result<MappedFile> open(const std::string& path);
  MappedFile() = default;
  MappedFile(MappedFile&& other) noexcept { *this = std::move(other); }
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  const uint8_t* data() const {
    return mapping_ ? static_cast<const uint8_t*>(mapping_) : owned_.data();
  }
  size_t size() const { return mapping_ ? mapped_size_ : owned_.size(); }

 private:
  void* mapping_ = nullptr;
  size_t mapped_size_ = 0;
  std::vector<uint8_t> owned_;
};

}  // namespace smpl
