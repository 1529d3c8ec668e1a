// Worker threads, as every parallel loop of the project starts them: worker 0
// on the calling thread, the others on threads of their own, all joined
// before runWorkers returns. Builds without threads (WebAssembly without
// pthreads: SMPL_NO_THREADS) run the workers one after the other on the
// calling thread, which gives the same results: every loop that uses this
// splits its work so that no result depends on which worker computed it.
#pragma once

#include <functional>

namespace smpl {

// Calls work(w, workers) for each w in [0, workers) (workers < 1: one worker).
void runWorkers(int workers, const std::function<void(int worker, int workers)>& work);

// The number of threads the machine runs at once (at least 1; 1 without threads).
unsigned hardwareThreads();

}  // namespace smpl
