#include "core/math/eigen_blocking.h"

#include <Eigen/Core>
#include <mutex>

namespace smpl {

void useFixedEigenBlocking() {
  static std::once_flag once;
  std::call_once(once, [] { Eigen::setCpuCacheSizes(48 * 1024, 1024 * 1024, 32 * 1024 * 1024); });
}

}  // namespace smpl
