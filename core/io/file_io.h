// Whole-file reads and atomic writes. Outputs go to "<path>.tmp-<pid>" and are
// renamed into place, so a failed run leaves no partial file (DESIGN.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

// Regular files and pipes only: devices (/dev/zero), directories and sockets
// are refused ("<path>: not a regular file (a character device)"); every buffer
// size is checked against the memory budget (core/memory_budget.h) first.
Result<std::vector<uint8_t>> readFileBytes(const std::string& path);

// Write bytes atomically: temp file in the same directory, fsync, rename.
Status writeFileAtomic(const std::string& path, const void* data, size_t size);
inline Status writeFileAtomic(const std::string& path, const std::string& bytes) {
  return writeFileAtomic(path, bytes.data(), bytes.size());
}

// Last path component, used to name files in errors.
std::string baseName(const std::string& path);

// True if `path` ends with `suffix` (".json", ".npy", "/"), to tell file and
// archive member kinds apart by name.
bool hasSuffix(const std::string& path, const std::string& suffix);

}  // namespace smpl
