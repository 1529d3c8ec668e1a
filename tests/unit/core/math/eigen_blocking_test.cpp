// useFixedEigenBlocking (core/math/eigen_blocking.h): Eigen's cache sizes, and
// so its product blocking, no longer come from the CPU.
#include "core/math/eigen_blocking.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

namespace smpl {
namespace {

TEST(EigenBlocking, CacheSizesAreFixed) {
  useFixedEigenBlocking();
  useFixedEigenBlocking();  // a second call changes nothing
  EXPECT_EQ(Eigen::l1CacheSize(), 48 * 1024);
  EXPECT_EQ(Eigen::l2CacheSize(), 1024 * 1024);
  EXPECT_EQ(Eigen::l3CacheSize(), 32 * 1024 * 1024);
}

}  // namespace
}  // namespace smpl
