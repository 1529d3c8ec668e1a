#include "core/math/float_environment.h"

#if defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h>
#define SMPL_HAVE_MXCSR 1
#else
#define SMPL_HAVE_MXCSR 0
#endif

namespace smpl {

bool floatEnvironmentIsDefault() {
  if (std::fegetround() != FE_TONEAREST) return false;
#if SMPL_HAVE_MXCSR
  constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040, kRounding = 0x6000;
  if (_mm_getcsr() & (kFlushToZero | kDenormalsAreZero | kRounding)) return false;
#endif
  return true;
}

DefaultFloatEnvironment::DefaultFloatEnvironment() {
  if (floatEnvironmentIsDefault()) return;  // the usual case: nothing to set or restore
  restore_ = std::fegetenv(&saved_) == 0;
  std::fesetenv(FE_DFL_ENV);
#if SMPL_HAVE_MXCSR
  // FE_DFL_ENV's MXCSR has FTZ and DAZ off on glibc; mingw and others may keep them.
  _mm_setcsr(_mm_getcsr() & ~0xE040u);
#endif
}

DefaultFloatEnvironment::~DefaultFloatEnvironment() {
  if (restore_) std::fesetenv(&saved_);
}

}  // namespace smpl
