// One memory budget for everything a run reads or builds: file bytes, inflated
// archive members, decoded arrays, motion frames, resampled animation frames.
// Each place that is about to allocate something whose size comes from an
// input asks the budget first, so a hostile or broken file gets a one-line
// error ("walk.npz: 'poses' as doubles would need 3.6 GiB in total; the limit
// is 2.0 GiB, set --memory-limit") instead of std::bad_alloc or the OOM killer.
//
// Design: the budget is process-wide (one limit, one atomic counter of bytes
// currently charged), not an object threaded through every loader. Every
// reader already takes a context string; adding a budget parameter to each of
// them would touch every signature for no gain, since a run has exactly one
// limit. Batch mode runs several jobs on threads: the counter is atomic, so
// their charges add up and the limit holds for the whole process.
// Charges are RAII (MemoryCharge): what holds the memory (an Array, a Motion,
// a ZipEntry, an AnimationClip) holds the charge, and releases it when it is
// destroyed. Copying a charged object copies the charge (unchecked: the copy
// already exists), so the counter follows the data.
//
//   MemoryCharge c;
//   if (Status st = c.add(n * sizeof(double), "walk.npz", "'poses' as doubles"); !st) return st;
//   data.resize(n);
#pragma once

#include <cstdint>
#include <string>

#include "core/result.h"

namespace smpl {

// Bytes charged against the process-wide limit until destroyed or released.
class MemoryCharge {
 public:
  MemoryCharge() = default;
  ~MemoryCharge() { release(); }
  MemoryCharge(const MemoryCharge& other);  // charges the same bytes again
  MemoryCharge& operator=(const MemoryCharge& other);
  MemoryCharge(MemoryCharge&& other) noexcept : bytes_(other.bytes_) { other.bytes_ = 0; }
  MemoryCharge& operator=(MemoryCharge&& other) noexcept;

  // Adds `bytes` if the process total stays within the limit. Otherwise
  // nothing is charged and the error reads
  // "<context>: <what> would need <total>; the limit is <limit>, set --memory-limit".
  Status add(uint64_t bytes, const std::string& context, const std::string& what);
  void release();
  uint64_t bytes() const { return bytes_; }

 private:
  uint64_t bytes_ = 0;
};

// Checks, without charging, that `bytes` more would fit: for short-lived
// buffers whose owner cannot hold a charge. Same error as MemoryCharge::add.
Status checkMemory(uint64_t bytes, const std::string& context, const std::string& what);

// The limit in bytes. Until setMemoryLimit() is called it is defaultMemoryLimit().
uint64_t memoryLimit();
void setMemoryLimit(uint64_t bytes);
// Bytes charged now by all threads.
uint64_t memoryCharged();

// min(8 GiB, 3/4 of physical memory): 8 GiB is several times the largest real
// job (an SMPL-X model with 400 shape/expression components decodes to about
// 0.4 GiB; long AMASS captures to tens of MB, resampled to a few hundred), and
// 3/4 of RAM leaves the rest of the machine room, so a run fails with an error
// before the kernel's OOM killer ends it without a word.
uint64_t defaultMemoryLimit();

// "512M", "4G", "1.5G", "300000000": a decimal number (core/number_text.h:
// no hexadecimal, sign or blanks) and K/M/G/T/P, powers of 1024, optionally
// followed by "iB" or "B"; no suffix means bytes. Refuses anything below
// 16 MiB or above 1 PiB.
Result<uint64_t> parseMemorySize(const std::string& text);

// "3.6 GiB", "512.0 MiB", "12 bytes": sizes in errors.
std::string formatBytes(uint64_t bytes);

}  // namespace smpl
