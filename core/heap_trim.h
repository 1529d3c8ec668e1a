// Handing freed heap memory back to the system. glibc keeps small freed
// blocks (a decoded motion frame is 1.7 KB) in its free lists, so freeing
// 100 MB of them does not lower the resident set; malloc_trim(0) releases
// every whole free page of every arena (madvise MADV_DONTNEED), after which
// the pages no longer count until touched again. Elsewhere (Windows, musl,
// WebAssembly) it does nothing: the memory is still reused by later
// allocations, only not returned.
#pragma once

namespace smpl {

// Returns the whole free pages of the heap to the system (glibc
// malloc_trim(0)); a no-op where the C library has no such call. Costs a
// walk over the free lists (about a millisecond for a few hundred MB).
void returnFreedHeap();

}  // namespace smpl
