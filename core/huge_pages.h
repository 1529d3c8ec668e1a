// Large freshly allocated buffers (decoded model arrays of tens of MB) are
// first touched one 4 KiB page at a time: a page fault each, about a third of
// a model load's time. adviseHugePages asks Linux to back the buffer's whole
// 2 MiB-aligned interior with transparent huge pages (madvise MADV_HUGEPAGE,
// what glibc's malloc does for every large allocation under the tunable
// glibc.malloc.hugetlb=1), so it faults 512 times less often. Call it after
// allocating and before writing. Only advice: a no-op for buffers under
// 4 MiB, on other systems, or where the kernel declines (THP "never").
#pragma once

#include <cstddef>

namespace smpl {

void adviseHugePages(void* data, size_t bytes);

}  // namespace smpl
