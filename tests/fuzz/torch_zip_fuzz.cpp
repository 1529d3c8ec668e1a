// libFuzzer entry point for torch.save archives (parseTorchZip: the zip
// directory, data.pkl, persistent ids, tensor strides and offsets against
// the storage records). Seeds: tests/fuzz/seeds/torch_zip/ (torch.save of
// small tensors: views of one storage, several dtypes).
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
  smpl::Result<smpl::DataNode> r = smpl::parseTorchZip(data, size, "fuzz.pt", limits);
  if (r.ok()) smpl::fuzz::touch(r.value());
  return 0;
}
