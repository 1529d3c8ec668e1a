// DefaultFloatEnvironment (core/math/float_environment.h): inside the guard
// the thread rounds to nearest and keeps subnormals, whatever was set before;
// the caller's environment is back afterwards.
#include "core/math/float_environment.h"

#include <gtest/gtest.h>

#include <cfenv>
#include <limits>
#if defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace smpl {
namespace {

double tenth(volatile double x) { return x / 10.0; }  // 0.1 rounds up to nearest
double third(volatile double x) { return x / 3.0; }  // of the smallest normal: an inexact subnormal

TEST(FloatEnvironment, GuardSetsTheDefaultAndRestores) {
  ASSERT_TRUE(floatEnvironmentIsDefault());
  const double nearest = tenth(1.0);
  const double tiny = std::numeric_limits<double>::min();  // the smallest normal double
  ASSERT_EQ(std::fesetround(FE_DOWNWARD), 0);
#if defined(__x86_64__)
  _mm_setcsr(_mm_getcsr() | 0x8040u);  // FTZ and DAZ, as -ffast-math's startup code sets them
  EXPECT_EQ(third(tiny), 0.0);         // flushed
#endif
  EXPECT_NE(tenth(1.0), nearest);
  EXPECT_FALSE(floatEnvironmentIsDefault());
  {
    DefaultFloatEnvironment guard;
    EXPECT_TRUE(floatEnvironmentIsDefault());
    EXPECT_EQ(tenth(1.0), nearest);
    EXPECT_GT(third(tiny), 0.0);  // a subnormal, not 0
  }
  EXPECT_EQ(std::fegetround(), FE_DOWNWARD);
#if defined(__x86_64__)
  EXPECT_EQ(_mm_getcsr() & 0x8040u, 0x8040u);
  _mm_setcsr(_mm_getcsr() & ~0x8040u);
#endif
  std::fesetround(FE_TONEAREST);
  EXPECT_TRUE(floatEnvironmentIsDefault());
}

}  // namespace
}  // namespace smpl
