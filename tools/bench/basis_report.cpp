// smpl-basis-report: what `--corrective-basis K` costs and saves, per model:
// the vertex error the truncation to K principal components adds (over
// samplePoses(K joints, 32, seed 1), e_i = |(P - B C) f|_i), the GLB and FBX
// size of an export with that budget, and the time the fit takes.
// Models: the built-in demo body and a synthetic SMPL-sized one (6890 x 207).
// Usage: smpl-basis-report (no options; --help/-h prints this usage, anything
// else is a usage error, exit 1).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"
#include "exporter/corrective_basis.h"
#include "exporter/pipeline.h"
#include "tools/bench/synthetic_model.h"
#include "writers/writer.h"

namespace smpl {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Bytes of `path`'s format for an export with K components (0 = every corrective).
size_t exportBytes(const BodyModel& model, int k, const char* path) {
  ExportOptions o;
  o.corrective_basis = k;
  Result<Asset> asset = buildAsset(model, o);
  if (!asset) return 0;
  Result<std::string> bytes = writerForPath(path)->serialize(*asset, WriterOptions());
  return bytes ? bytes->size() : 0;
}

void report(const char* title, const BodyModel& model) {
  const int p = model.numPoseFeatures();
  std::printf("\n%s: %d vertices, %d pose correctives\n", title, model.numVertices(), p);
  auto start = std::chrono::steady_clock::now();
  Result<CorrectiveBasisFit> fit = fitCorrectiveBasis(model.posedirs, p);
  if (!fit) {
    std::printf("  %s\n", fit.message().c_str());
    return;
  }
  std::printf("  fit (K = P, Gram eigen-decomposition + QR): %.2f s; numerical rank %d\n",
              secondsSince(start), static_cast<int>(fit->basis.cols()));
  start = std::chrono::steady_clock::now();
  const std::vector<BasisError> rows = basisErrorReport(model, {8, 16, 32, 64, 128, p}, 32, 1);
  std::printf("  error table: %.2f s\n", secondsSince(start));
  std::printf("  %5s %14s %14s %12s %12s\n", "K", "max error mm", "mean error mm", "GLB bytes",
              "FBX bytes");
  std::printf("  %5s %14s %14s %12zu %12zu\n", "all", "0", "0", exportBytes(model, 0, "x.glb"),
              exportBytes(model, 0, "x.fbx"));
  for (const BasisError& e : rows)
    std::printf("  %5d %14.4f %14.5f %12zu %12zu\n", e.components, 1e3 * e.max_error,
                1e3 * e.mean_error, exportBytes(model, e.components, "x.glb"),
                exportBytes(model, e.components, "x.fbx"));
}

}  // namespace
}  // namespace smpl

int main(int argc, char** argv) {
  using namespace smpl;
  const char* usage =
      "usage: smpl-basis-report\n"
      "Prints, for the built-in body and a synthetic SMPL-sized model, the vertex error\n"
      "--corrective-basis K adds (32 poses, seed 1), the GLB/FBX sizes and the fit time per K.\n";
  if (argc == 2 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")))
    return std::printf("%s", usage), 0;
  if (argc > 1)
    return std::fprintf(stderr, "smpl-basis-report: unknown argument '%s'\n%s", argv[1], usage), 1;
  std::printf(
      "smpl-basis-report: error the corrective basis adds (32 poses, seed 1), and export sizes\n");
  report("builtin", demoBody());
  report("synthetic SMPL", syntheticModel(ModelKind::Smpl, 6890, 10, 0, 1));
  return 0;
}
