// libFuzzer entry point for the C++ runtimes' sidecar reader
// (unreal/.../Public/SmplCorrectivesMetadata.h: JSON -> Layout), then one
// evaluation with the parsed layout. Seeds: tests/fuzz/seeds/sidecar/.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesMetadata.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl_correctives::Layout layout;
  std::string text(reinterpret_cast<const char*>(data), size);
  if (!smpl_correctives::parseLayout(text, &layout).empty() || layout.parents.size() > 4096)
    return 0;
  smpl_correctives::Evaluator ev;
  std::vector<smpl_correctives::Mat3> rest(layout.parents.size(), smpl_correctives::identity());
  if (!ev.bind(layout, smpl_correctives::unrealFbxAxes(), rest).empty()) return 0;
  std::vector<smpl_correctives::Mat3> now(rest.size(),
                                          smpl_correctives::fromQuaternion(0.1, 0.2, 0.3, 0.9));
  ev.evaluate(now);
  volatile double sink = 0;
  for (double w : ev.weights()) sink = sink + w;
  return 0;
}
