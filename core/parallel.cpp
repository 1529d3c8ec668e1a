#include "core/parallel.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace smpl {

void runWorkers(int workers, const std::function<void(int worker, int workers)>& work) {
  workers = std::max(1, workers);
#ifdef SMPL_NO_THREADS
  for (int w = 0; w < workers; ++w) work(w, workers);
#else
  std::vector<std::thread> pool;
  pool.reserve(size_t(workers - 1));
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w, workers);
  work(0, workers);
  for (std::thread& t : pool) t.join();
#endif
}

unsigned hardwareThreads() {
#ifdef SMPL_NO_THREADS
  return 1;
#else
  return std::max(1u, std::thread::hardware_concurrency());
#endif
}

}  // namespace smpl
