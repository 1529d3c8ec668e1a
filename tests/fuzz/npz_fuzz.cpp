// libFuzzer entry point for the .npz reader (zip container + .npy members).
// Seeds: tests/fuzz/seeds/npz/ and build/fixtures/npy_cases/*.npz.
#include <cstddef>
#include <cstdint>

#include "core/io/npz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl::Result<smpl::ArrayDict> r = smpl::parseNpz(data, size, "fuzz.npz");
  if (r.ok()) {
    // Touch every value so a bad shape/size pairing would show up under ASan.
    double sum = 0;
    for (const auto& kv : r.value()) {
      sum += static_cast<double>(kv.second.size());
      for (double v : kv.second.data) sum += v;
      for (const auto& s : kv.second.strings) sum += static_cast<double>(s.size());
    }
    volatile double sink = sum;
    (void)sink;
  }
  return 0;
}
