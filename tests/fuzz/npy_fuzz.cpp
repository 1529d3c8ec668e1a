// libFuzzer entry point for the .npy reader. Seeds: tests/fuzz/seeds/npy/
// and build/fixtures/npy_cases/*.npy.
#include <cstddef>
#include <cstdint>

#include "core/io/npy.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl::Result<smpl::Array> r = smpl::parseNpy(data, size, "fuzz.npy");
  if (r.ok()) {
    // Touch every value so a bad shape/size pairing would show up under ASan.
    const smpl::Array& a = r.value();
    double sum = static_cast<double>(a.size());
    for (double v : a.data) sum += v;
    for (const auto& s : a.strings) sum += static_cast<double>(s.size());
    volatile double sink = sum;
    (void)sink;
  }
  return 0;
}
