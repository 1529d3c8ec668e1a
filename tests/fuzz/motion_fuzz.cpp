// libFuzzer entry point for the motion reader (core/motions/motion: .npz and
// .json motions, split AMASS keys, rotation matrices, frame rates, betas).
// loadMotion reads a path, so each input is written to a private temporary
// file; the first byte picks the format (odd: .json, even: .npz) and the rest
// is the file. The memory budget is 1 GiB, below libFuzzer's -rss_limit_mb,
// so a hostile size must end in the budget's error, never in an OOM report.
// Seeds: tests/fuzz/seeds/motion/ (first byte 0 = npz, 1 = json).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/memory_budget.h"
#include "core/motions/motion.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  smpl::setMemoryLimit(1ull << 30);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string path =
      "/tmp/smpl_motion_fuzz_" + std::to_string(::getpid()) + ((data[0] & 1) ? ".json" : ".npz");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  smpl::Result<smpl::Motion> m = smpl::loadMotion(path);
  if (m.ok()) {
    // Touch every value so a bad size pairing would show up under ASan.
    double sum = m->fps;
    for (const auto& frame : m->frames)
      for (const auto& r : frame) sum += r.sum();
    for (const auto& t : m->translation) sum += t.sum();
    for (double b : m->betas) sum += b;
    volatile double sink = sum;
    (void)sink;
  }
  std::remove(path.c_str());
  return 0;
}
