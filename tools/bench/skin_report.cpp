// smpl-skin-report: what fitted skin weights (--skin-weights optimized,
// core/math/skin_weight_fit.h) gain over truncation, per model: the held-out
// vertex error (exporter/pruning_error.h: 32 poses, seed 20261124, never used
// for training) of truncated and optimised weights for M = 1, 2, 4, 8
// influences (mean and max, mm), and the time the fit takes.
//   smpl-skin-report [MODEL ...]      the built-in body, then each model file
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"
#include "core/load/model_loader.h"
#include "core/math/skin_weights.h"
#include "exporter/export_skin.h"
#include "exporter/pruning_error.h"

namespace smpl {
namespace {

constexpr int kHeldOutPoses = 32;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One row: M, truncated mean/max, optimised mean/max, mean gain, fit time.
bool reportRow(const BodyModel& model, int m) {
  ExportOptions o;
  o.max_influences = m;
  const Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  if (!body) return std::printf("  %s\n", body.message().c_str()), false;
  Result<SkinError> t = measureSkinError(
      model, o, denseWeights(pruneWeights(model.weights, m), model.numJoints()), kHeldOutPoses);
  const auto start = std::chrono::steady_clock::now();
  o.skin_weights = SkinWeightMethod::Optimized;
  const SparseSkin fit = exportSkin(model, *body, o);
  const double seconds = secondsSince(start);
  Result<SkinError> f =
      measureSkinError(model, o, denseWeights(fit, model.numJoints()), kHeldOutPoses);
  if (!t || !f) return std::printf("  %s\n", (t ? f.message() : t.message()).c_str()), false;
  const double gain = t->mean_m > 0 ? 100.0 * (1.0 - f->mean_m / t->mean_m) : 0.0;
  std::printf("| %d | %.4f | %.4f | %.4f | %.4f | %.0f%% | %.0f |\n", m, t->mean_m * 1e3,
              t->max_m * 1e3, f->mean_m * 1e3, f->max_m * 1e3, gain, seconds * 1e3);
  return true;
}

bool report(const std::string& title, const BodyModel& model) {
  std::printf("\n%s: %d vertices, %d joints (held-out: %d poses)\n\n", title.c_str(),
              model.numVertices(), model.numJoints(), kHeldOutPoses);
  std::printf(
      "| M | truncated mean mm | truncated max mm | optimized mean mm | optimized max mm | mean "
      "gain | fit ms |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  bool ok = true;
  for (int m : {1, 2, 4, 8})
    if (m <= model.numJoints()) ok = reportRow(model, m) && ok;
  return ok;
}

}  // namespace
}  // namespace smpl

int main(int argc, char** argv) {
  using namespace smpl;
  bool ok = report("builtin", demoBody());
  for (int i = 1; i < argc; ++i) {
    Result<BodyModel> model = loadModel(argv[i]);
    if (!model) {
      std::fprintf(stderr, "Error loading %s\n", model.message().c_str());
      return 2;
    }
    ok = report(argv[i], *model) && ok;
  }
  return ok ? 0 : 3;
}
