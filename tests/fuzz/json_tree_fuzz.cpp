// libFuzzer entry point for JSON as a tree (parseJsonTree: the depth scan
// before parsing, the numeric-nest detection, text). Seeds:
// tests/fuzz/seeds/json_tree/.
#include <cstddef>
#include <cstdint>

#include "core/io/tree/json_tree.h"
#include "tests/fuzz/touch_tree.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl::Result<smpl::DataNode> r = smpl::parseJsonTree(data, size, "fuzz.json");
  if (r.ok()) smpl::fuzz::touch(r.value());
  return 0;
}
