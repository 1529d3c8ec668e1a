// The floating-point environment every output is computed in: round to
// nearest, no flush of subnormal results or inputs to zero (x86's MXCSR FTZ
// and DAZ bits off), as a process starts. A host process can change it for
// its thread (torch.set_flush_denormal, a library built with -ffast-math
// that sets FTZ/DAZ at load, fesetround), and then the same sums round
// differently: the Python module exports inside this guard, so its bytes are
// the CLI's whatever its host did. Threads started inside inherit it.
#pragma once

#include <cfenv>

namespace smpl {

// True if this thread rounds to nearest and, on x86-64, neither flushes
// subnormal results (FTZ) nor treats subnormal inputs as zero (DAZ).
bool floatEnvironmentIsDefault();

// Sets this thread's floating-point environment to the default (FE_DFL_ENV)
// for the guard's lifetime and restores the caller's afterwards.
class DefaultFloatEnvironment {
 public:
  DefaultFloatEnvironment();
  ~DefaultFloatEnvironment();
  DefaultFloatEnvironment(const DefaultFloatEnvironment&) = delete;
  DefaultFloatEnvironment& operator=(const DefaultFloatEnvironment&) = delete;

 private:
  std::fenv_t saved_;
  bool restore_ = false;
};

}  // namespace smpl
