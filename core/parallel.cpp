#include "core/parallel.h"

#include <algorithm>
#include <exception>
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

void runTogether(bool together, const std::function<void()>& first,
                 const std::function<void()>& second) {
#ifdef SMPL_NO_THREADS
  together = false;
#endif
  if (!together) {
    first();
    second();
    return;
  }
  std::exception_ptr failed;
  std::thread other([&] {
    try {
      second();
    } catch (...) {
      failed = std::current_exception();
    }
  });
  try {
    first();
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (failed) std::rethrow_exception(failed);
}

unsigned hardwareThreads() {
#ifdef SMPL_NO_THREADS
  return 1;
#else
  return std::max(1u, std::thread::hardware_concurrency());
#endif
}

}  // namespace smpl
