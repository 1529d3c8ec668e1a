// Reading a memory-mapped input must not kill the process when the file
// shrinks underneath it (another process truncates or rewrites it in place)
// or its pages cannot be read (an I/O error): the kernel then raises SIGBUS
// on the next access to a page beyond the new end. A MappingGuard registers a
// mapping with a process-wide SIGBUS handler; on such a fault inside a
// registered mapping the handler maps zero-filled pages over the rest of it
// (from the faulting page to its end), marks the mapping lost and returns, so
// the interrupted read goes on reading zeros. Readers check lost() when they
// are done with the bytes (and on their error paths) and report the file:
//   "<file>: cannot read: the file shrank while it was being read (...)"
// Faults elsewhere go to the handler that was installed before (or the
// default action: the process dies with SIGBUS as it would have).
//
// Why not sigsetjmp/siglongjmp around each read: a long jump out of a parser
// skips destructors of the C++ objects it was building (undefined behaviour
// and leaks), and every read path would need the wrapper. The zero pages keep
// every reader as it is: the parsers already treat their input as hostile, so
// zeros only lead to an error or a value that is then discarded. No cost on
// the read path (registration is two atomic stores per mapping).
#pragma once

#include <cstddef>
#include <string>

#include "core/result.h"

namespace smpl {

class MappingGuard {
 public:
  MappingGuard() = default;
  // Watches [data, data + size); watching() is false when every one of the
  // kMaxWatched slots is taken (the caller then reads the file instead).
  MappingGuard(const void* data, size_t size);
  MappingGuard(MappingGuard&& other) noexcept;
  MappingGuard& operator=(MappingGuard&& other) noexcept;
  MappingGuard(const MappingGuard&) = delete;
  MappingGuard& operator=(const MappingGuard&) = delete;
  ~MappingGuard();  // stops watching; call before munmap

  bool watching() const { return slot_ >= 0; }
  // True once a read faulted (the file shrank or could not be read).
  bool lost() const;

  static constexpr int kMaxWatched = 256;

 private:
  void release();
  int slot_ = -1;
};

// The error for a lost mapping of `path` (one line, names the file).
Error mappingLostError(const std::string& path);

}  // namespace smpl
