// libFuzzer entry point for the data-only unpickler. Limits are tighter than
// the defaults so that a "billion laughs" memo graph hits the byte budget
// instead of libFuzzer's RSS limit. Seeds: build/fixtures/pickle_cases/*.pkl.
#include <cstddef>
#include <cstdint>

#include "core/io/pickle/pickle.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl::PickleLimits limits;
  limits.max_memo = 1u << 16;
  limits.max_stack_depth = 1u << 12;
  limits.max_total_bytes = 64u << 20;
  smpl::Result<smpl::ArrayDict> r = smpl::parsePickle(data, size, "fuzz.pkl", limits);
  if (r.ok()) {
    // Touch every value so a bad shape/size pairing would show up under ASan.
    double sum = 0;
    for (const auto& kv : r.value()) {
      for (double v : kv.second.data) sum += v;
      for (const auto& s : kv.second.strings) sum += static_cast<double>(s.size());
    }
    volatile double sink = sum;
    (void)sink;
  }
  return 0;
}
