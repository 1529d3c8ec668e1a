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

// Runs `first` on the calling thread and, with `together`, `second` on a
// thread of its own at the same time (without it, or without threads:
// `first`, then `second`, which does not run if `first` throws). For two
// independent stages where one leaves a core idle: a serial load beside a
// hash, a serial write beside a measurement. Together, a throw of either
// reaches the caller only once both have returned (the first's wins).
void runTogether(bool together, const std::function<void()>& first,
                 const std::function<void()>& second);

// The number of threads the machine runs at once (at least 1; 1 without threads).
unsigned hardwareThreads();

}  // namespace smpl
