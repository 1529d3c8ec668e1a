// Whole-file reads and atomic writes. Outputs go to a temporary file
// "<dir>/.<name>.smpl.tmp-<pid>" and are renamed into place, so a failed run
// leaves no partial file (docs/file-contract.md). A run killed mid-write (SIGKILL) leaves
// at most such dot-prefixed temporaries, named after the output; the next run
// writing that output removes them (removeStaleTemps).
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

// Several files committed together (an output and its sidecar): either all
// are replaced or none. Protocol:
//   1. every file is written to its temporary and fsynced (a failure removes
//      the temporaries; nothing else was touched);
//   2. each existing old file is kept as a backup: hard link
//      ".<name>.smpl.tmp-<pid>-old" (or, where hard links are unsupported, the
//      old file is renamed to it);
//   3. the temporaries are renamed into place in the order given; if rename i
//      fails, files 0..i-1 are restored from their backups (or removed when
//      there was no old file) and the error is returned;
//   4. the backups are removed and the directory is fsynced.
// The LAST file is the commit record: a crash between renames leaves the new
// earlier files with the old last file, so callers put the file that records
// what produced the set (the sidecar) last. A crash leaves at most
// dot-prefixed temporaries and backups, which removeStaleTemps removes.
struct FileContent {
  std::string path;
  const void* data;  // not owned
  size_t size;
};
Status writeFilesTogether(const std::vector<FileContent>& files);

// Temporary file of `path` for this process: "<dir>/.<name>.smpl.tmp-<pid>".
std::string tempPathFor(const std::string& path);

// Removes, in `dir`, temporaries (and backups) of the outputs named in
// `names` (base names) left by runs that are gone: the pid in the name is not
// a live process, or the file is older than 24 hours (pid reuse). Files of
// live runs and every other file are left alone. Returns how many were
// removed; errors (unreadable dir) are ignored: cleanup is best effort.
int removeStaleTemps(const std::string& dir, const std::vector<std::string>& names);

// Directory part of a path ("." when there is none).
std::string dirName(const std::string& path);

// Last path component, used to name files in errors.
std::string baseName(const std::string& path);

// True if `path` ends with `suffix` (".json", ".npy", "/"), to tell file and
// archive member kinds apart by name.
bool hasSuffix(const std::string& path, const std::string& suffix);

}  // namespace smpl
