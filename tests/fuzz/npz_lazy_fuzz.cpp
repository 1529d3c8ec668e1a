// libFuzzer entry point for the lazy .npz path the loaders use: NpzArchive
// (central-directory listing, one member at a time) and readNpzMember, which
// sends object-dtype ('|O') members through the data-only unpickler.
// Seeds: build/fixtures/released/*.npz and tests/fuzz/seeds/npz/.
#include <cstddef>
#include <cstdint>

#include "core/models/npz_arrays.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  smpl::Result<smpl::NpzArchive> npz = smpl::NpzArchive::fromBytes(data, size, "fuzz.npz");
  if (!npz.ok()) return 0;
  double sum = 0;
  for (const std::string& key : npz.value().keys()) {
    smpl::Result<smpl::Array> a = smpl::readNpzMember(npz.value(), key);
    if (!a.ok()) continue;
    // Touch every value so a bad shape/size pairing would show up under ASan.
    sum += static_cast<double>(a.value().size());
    for (double v : a.value().data) sum += v;
    for (const auto& s : a.value().strings) sum += static_cast<double>(s.size());
    for (const auto& k : a.value().keys) sum += static_cast<double>(k.size());
  }
  volatile double sink = sum;
  (void)sink;
  return 0;
}
