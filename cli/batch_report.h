// What batch mode prints as it goes, kept apart from the batch loop so that it
// can be tested without running exports: the `[k/N]` prefix of each finished
// file (with an estimate of the time left when the output is a terminal), and
// the notes of all motions folded so that a note every motion repeats (the
// DMPL hint of 20 AMASS motions) is printed once with its count.
#pragma once

#include <string>
#include <vector>

#include "request/export_request.h"

namespace smpl {

// "[k/N] " for the k-th finished of N files; with `eta` (a terminal), the time
// left as "[k/N, ETA m:ss] ", estimated from `elapsed_s` seconds for k files
// (elapsed / k per remaining file; nothing once k == N).
std::string batchProgressPrefix(size_t k, size_t n, double elapsed_s, bool eta);

// The batch's throughput line, after the files: "batch: K motions in W s
// (R motions/s); time in read A%, fit B%, bake C%, write D%". `wall_s` is the
// batch's wall time; `summed` the converted exports' stage times summed over
// every worker (request/export_request.h StageSeconds), so the percentages
// are shares of the export work, whatever the number of threads (they sum to
// 100 up to rounding; all 0 when no time was measured). Empty for no motions.
std::string batchThroughputLine(int converted, double wall_s, const StageSeconds& summed);

// "m:ss" (or "h:mm:ss" from an hour) of a non-negative number of seconds, rounded up.
std::string formatDuration(double seconds);

// Notes of a batch: each motion's notes, in motion order, and then one line
// per distinct note. A note that starts with the motion's name ("walk: ...",
// as the export writes per-motion notes) is compared without it, so the same
// hint for many motions is one line "<text> (K motions)"; a note only one
// motion has keeps its name.
class BatchNotes {
 public:
  explicit BatchNotes(size_t motions) : per_motion_(motions) {}
  // Thread-compatible: each index is written by one worker.
  void set(size_t index, const std::string& motion_name, std::vector<std::string> notes);
  // The folded lines (without "note: "), in the order of their first motion.
  std::vector<std::string> folded() const;

 private:
  struct Entry {
    std::string name;
    std::vector<std::string> notes;
  };
  std::vector<Entry> per_motion_;
};

}  // namespace smpl
