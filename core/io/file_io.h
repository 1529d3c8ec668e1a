// Whole-file reads and atomic writes (docs/file-contract.md "Files").
//
// Reads: readFileBytes refuses devices and charges the memory budget;
// checkInputFile / readFileBytes(path, kind) also refuse, from the first
// bytes and the size, a file that is not what its kind claims
// (core/io/input_kind.h), before it is read whole.
//
// Writes: an output is written to a temporary in its own folder,
//   "<dir>/.<name>.smpl.tmp-<tag>-<random>"
// <name> the output's name (cut to 215 bytes so that every legal name, up to
// NAME_MAX = 255 bytes, has a temporary), <tag> 8 hex digits of a hash of the
// whole name (tells the temporaries of two long names apart), <random> 16 hex
// digits from getrandom(2). The temporary is created with O_CREAT | O_EXCL |
// O_NOFOLLOW (a file or a symbolic link planted under that name is never
// opened, followed or truncated: a new name is drawn), mode 0666 & ~umask, and
// its writer holds an flock(2) on it until the commit is over. Then it is
// renamed into place; rename(2) replaces a symbolic link at the output's name
// instead of following it. A run killed mid-write (SIGKILL) leaves at most such
// dot-prefixed temporaries; the next run writing that output removes those no
// live process holds locked (removeStaleTemps).
//
// Concurrent writers of the same output (two processes, or batch threads):
// commits are serialised by an exclusive flock on the output's folder, so the
// last commit wins every file of the set and the files on disk always come
// from one run. Temporaries are created under a shared lock of the folder and
// stale ones removed under the exclusive lock, so a cleanup never sees a
// temporary in the instant between its creation and its writer's flock.
// Where locks are unsupported (ENOLCK) writes go ahead unlocked, and a
// temporary that cannot be locked is never taken for stale (it stays).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/byte_span.h"
#include "core/io/input_kind.h"
#include "core/result.h"

namespace smpl {

// Regular files and pipes only: devices (/dev/zero), directories and sockets
// are refused ("<path>: not a regular file (a character device)"); every buffer
// size is checked against the memory budget (core/memory_budget.h) first.
Result<std::vector<uint8_t>> readFileBytes(const std::string& path);

// readFileBytes for a file of `kind`: its first bytes must show one of the
// kind's formats and its size must be within that format's bound, checked
// before the rest is read (a pipe is read up to the bound). Errors:
//   "<path>: not a UV file (expected .npy; the file starts with '\x00\x00...')"
//   "<path>: 3.0 GiB is too large for a UV file in .npy (at most 256.0 MiB)"
//   "<path>: not a regular file (a pipe); a model file must be a regular file"
Result<std::vector<uint8_t>> readFileBytes(const std::string& path, const InputKind& kind);

// The same checks without reading the file: the format its first bytes show
// (for readers that map the file or dispatch on the format). A pipe of a kind
// that allows pipes cannot be sniffed without consuming it: FileFormat::Unknown
// is returned and the caller reads it with readFileBytes(path, kind).
Result<FileFormat> checkInputFile(const std::string& path, const InputKind& kind);

// Write bytes atomically: a temporary in the same directory, fsync, rename.
Status writeFileAtomic(const std::string& path, const void* data, size_t size);
inline Status writeFileAtomic(const std::string& path, const std::string& bytes) {
  return writeFileAtomic(path, bytes.data(), bytes.size());
}

// Several files committed together (an output, its .bin, its sidecar): either
// all are replaced or none. Protocol:
//   1. every file is written to its own temporary (above) and fsynced; a
//      failure removes the temporaries (nothing else was touched);
//   2. under the exclusive lock of the files' folders, each existing old file
//      is kept as a backup "<its temporary>-old": a hard link (link(2) links a
//      symbolic link itself, never its target), or, where hard links are
//      unsupported, the old file renamed to it;
//   3. the temporaries are renamed into place in the order given; if rename i
//      fails, files 0..i-1 are restored from their backups (or removed when
//      there was no old file) and the error is returned;
//   4. the backups are removed, the folders fsynced, the lock released.
// The LAST file is the commit record: a crash between renames leaves the new
// earlier files with the old last file, so callers put the file that records
// what produced the set (the sidecar) last. A crash leaves at most
// dot-prefixed temporaries and backups, which removeStaleTemps removes.
// A file whose name is longer than NAME_MAX (255 bytes) fails before anything
// is written: "<path>: cannot create: File name too long".
struct FileContent {
  std::string path;
  const void* data;  // not owned
  size_t size;
  // Bytes the file holds after `data`, in order (not owned): a GLB's BIN
  // chunk, written from the writer's buffer and the asset's own arrays
  // rather than copied behind its header first.
  std::vector<ByteSpan> tail = {};
  size_t totalSize() const;  // size + the tail's sizes
};
Status writeFilesTogether(const std::vector<FileContent>& files);

// writeFilesTogether(files + the record), where the record (the last file,
// at `record_path`) is the text `make_record` returns: with `together` it is
// made on a thread of its own while `files` are written and fsynced, so a
// sidecar that hashes them waits neither for the disk nor the disk for it.
// `make_record` may read the files' bytes (they are only read here). If it
// throws, the temporaries are removed and the exception goes on.
Status writeFilesWithRecord(const std::vector<FileContent>& files, const std::string& record_path,
                            const std::function<std::string()>& make_record, bool together);

// A fresh temporary name for `path`, "<dir>/.<name>.smpl.tmp-<tag>-<random>"
// (a new random part on every call; nothing is created).
std::string tempPathFor(const std::string& path);

// For tests only: the random part of the next temporary names comes from
// `source` (16 lowercase hex digits per call; nullptr: getrandom again), so a
// test can plant a file or a link under the very name a write will draw and
// see that it is never opened or followed and another name is drawn.
void setTempRandomForTesting(std::string (*source)());

// Tests only: `hook` (nullptr: none) runs in writeFilesTogether after each
// file of the set is renamed into place, under the folder lock, with the index
// of that file; a test pauses there to widen the window in which a second
// writer of the same outputs could interleave its renames (it must wait).
void setCommitHookForTesting(void (*hook)(size_t index));

// Removes, in `dir`, the temporaries (and backups) of the outputs named in
// `names` (base names) that no live writer holds: each is a regular file whose
// name is exactly a temporary name of one of `names`, and an flock on it
// succeeds (its writer is gone; the lock dies with the process). Files of live
// writers and every other file (other outputs' temporaries, links, folders)
// are left alone. Returns how many were removed; errors (unreadable dir) are
// ignored: cleanup is best effort.
int removeStaleTemps(const std::string& dir, const std::vector<std::string>& names);

// Directory part of a path ("." when there is none).
std::string dirName(const std::string& path);

// Last path component, used to name files in errors.
std::string baseName(const std::string& path);

// True if `path` ends with `suffix` (".json", ".npy", "/"), to tell file and
// archive member kinds apart by name.
bool hasSuffix(const std::string& path, const std::string& suffix);

}  // namespace smpl
