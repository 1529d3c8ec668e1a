// Wall time in seconds since an instant of the steady clock: an export's stage
// times (request/export_request.h StageSeconds), the batch's clock and the
// bake's progress bar read it the same way.
//
//   const SteadyTime start = steadyNow();
//   ...
//   report.seconds = secondsSince(start);
#pragma once

#include <chrono>

namespace smpl {

using SteadyTime = std::chrono::steady_clock::time_point;

inline SteadyTime steadyNow() { return std::chrono::steady_clock::now(); }

// Seconds from `start` to now; never negative (the steady clock does not go back).
inline double secondsSince(SteadyTime start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace smpl
