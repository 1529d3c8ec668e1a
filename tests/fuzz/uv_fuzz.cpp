// libFuzzer entry point for the OBJ UV reader (core/models/uv_obj, `--uv`).
// The first byte sets the model's vertex count (0..255) so the face index
// checks are exercised against both small and matching meshes; the rest is
// the OBJ text, written to a private temporary file (the reader takes a path).
// Seeds: tests/fuzz/seeds/uv/.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/memory_budget.h"
#include "core/models/uv_obj.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  smpl::setMemoryLimit(1ull << 30);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  smpl::BodyModel model;
  model.v_template = Eigen::MatrixXd::Zero(data[0], 3);
  const std::string path = "/tmp/smpl_uv_fuzz_" + std::to_string(::getpid()) + ".obj";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  smpl::Result<smpl::UvLayout> uv = smpl::loadUvLayout(path, model);
  if (uv.ok()) {
    // Every index must be in range: read through them.
    float sum = 0;
    for (Eigen::Index i = 0; i < uv->triangles.size(); ++i)
      sum += uv->uvs(uv->triangles.data()[i], 0);
    for (int v : uv->source_vertex) sum += static_cast<float>(model.v_template(v, 0));
    volatile float sink = sum;
    (void)sink;
  }
  std::remove(path.c_str());
  return 0;
}
