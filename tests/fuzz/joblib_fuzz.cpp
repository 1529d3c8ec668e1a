// libFuzzer entry point for joblib files (parseJoblib: the wrapper arrays
// after BUILD, the inline object pickles, zlib/gzip inflation) and the tree
// conversion. Limits are tighter than the defaults so that memo graphs and
// bombs hit the pickle's bound instead of libFuzzer's RSS limit.
// Seeds: tests/fuzz/seeds/joblib/ (joblib.dump of small dicts, plain and zlib).
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
  smpl::Result<smpl::DataNode> r = smpl::parseJoblib(data, size, "fuzz.pkl", limits);
  if (r.ok()) smpl::fuzz::touch(r.value());
  return 0;
}
