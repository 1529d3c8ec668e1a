// A whole input file's bytes without copying them: a read-only private
// mapping of a regular file (the pages come straight from the page cache and
// are mapped as they are read, so a reader that only sniffs the first bytes
// or the zip directory of a huge file touches a few pages), or, for what
// cannot be mapped (pipes, empty files), readFileBytes' copy with its checks
// (devices refused, memory budget). The mapping is watched by a MappingGuard
// (mapping_guard.h): a file that shrinks while it is read gives the reader
// zeros instead of SIGBUS, and intact() the error naming the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/io/mapping_guard.h"
#include "core/os/files.h"
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

  const uint8_t* data() const { return mapping_.data() ? mapping_.data() : owned_.data(); }
  size_t size() const { return mapping_.data() ? mapping_.size() : owned_.size(); }

  // Ok while every byte read so far is the file's; after the file shrank
  // under the mapping (zeros were read instead), mappingLostError(path).
  // Readers call it when done with the bytes, whatever their own result.
  Status intact() const;
  // True once a read of the mapping faulted (intact() then fails).
  bool lost() const { return guard_.lost(); }

 private:
  void unmap();
  os::FileMapping mapping_;
  MappingGuard guard_;
  std::string path_;
  std::vector<uint8_t> owned_;
};

}  // namespace smpl
