// libFuzzer entry point for .npy images as trees (parseNpyTree: numeric
// arrays, and object arrays whose payload is a pickle: np.save'd dicts,
// arrays of dicts). Seeds: tests/fuzz/seeds/npy_object/.
#include <cstddef>
#include <cstdint>

#include "core/io/pickle/pickle_tree.h"
#include "tests/fuzz/touch_tree.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl::PickleLimits limits;
  limits.max_memo = 1u << 16;
  limits.max_stack_depth = 1u << 12;
  limits.max_total_bytes = 64u << 20;
  limits.expansion_floor = 16u << 20;
  smpl::Result<smpl::DataNode> r = smpl::parseNpyTree(data, size, "fuzz.npy", limits);
  if (r.ok()) smpl::fuzz::touch(r.value());
  return 0;
}
