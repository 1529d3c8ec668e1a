// smpl-skin-report: what fitted skin weights (--skin-weights optimized,
// core/math/skin_weight_fit.h) gain over truncation, per model: the held-out
// vertex error (exporter/pruning_error.h: 32 poses, seed 20261124, never used
// for training) of truncated and optimised weights for M = 1, 2, 4, 8
// influences (mean and max, mm), and the time the fit takes. "bound": the
// same fit trained on the held-out poses themselves (no prior, no guard,
// every support subset it can afford, summed distance minimised): a lower
// bound on the held-out mean any weights with such supports reach, so a
// mean gain above "bound gain" cannot be had on that body.
//   smpl-skin-report [--poses N] [MODEL ...]   the built-in body, then each model file;
//                                              N held-out poses (default 32)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"
#include "core/load/model_loader.h"
#include "core/math/skin_weight_fit.h"
#include "core/math/skin_weights.h"
#include "exporter/export_skin.h"
#include "exporter/pruning_error.h"

namespace smpl {
namespace {

int held_out_poses = 32;                     // --poses
constexpr uint64_t kHeldOutSeed = 20261124;  // exporter/pruning_error.h's poses

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The fit trained on the held-out poses themselves (see the file comment).
SparseSkin boundSkin(const BodyModel& model, const ShapedBody& body, int m) {
  SkinFitOptions o;
  o.max_influences = m;
  o.training_poses = held_out_poses;
  o.seed = kHeldOutSeed;
  o.prior_strength = 0.0;
  o.guard = false;
  o.exhaustive_limit = 1000;
  o.l1_iterations = 30;
  return fitSkinWeights(model, body, o);
}

// "12%", or "-" when truncation is exact to 1 nm (the ratio of rounding
// residues means nothing: M at least the influences of every vertex).
std::string gainPercent(double fitted, double truncated) {
  if (truncated < 1e-9) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * (1.0 - fitted / truncated));
  return text;
}

// One row: M, truncated mean/max, optimised mean/max, mean gain, bound mean
// and gain, fit time.
bool reportRow(const BodyModel& model, int m) {
  ExportOptions o;
  o.max_influences = m;
  const Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  if (!body) return std::printf("  %s\n", body.message().c_str()), false;
  const int k = model.numJoints();
  Result<SkinError> t =
      measureSkinError(model, o, denseWeights(pruneWeights(model.weights, m), k), held_out_poses);
  const auto start = std::chrono::steady_clock::now();
  o.skin_weights = SkinWeightMethod::Optimized;
  const SparseSkin fit = exportSkin(model, *body, o);
  const double seconds = secondsSince(start);
  Result<SkinError> f = measureSkinError(model, o, denseWeights(fit, k), held_out_poses);
  Result<SkinError> b =
      measureSkinError(model, o, denseWeights(boundSkin(model, *body, m), k), held_out_poses);
  for (const Result<SkinError>* e : {&t, &f, &b})
    if (!*e) return std::printf("  %s\n", e->message().c_str()), false;
  std::printf("| %d | %.4f | %.4f | %.4f | %.4f | %s | %.4f | %s | %.0f |\n", m, t->mean_m * 1e3,
              t->max_m * 1e3, f->mean_m * 1e3, f->max_m * 1e3,
              gainPercent(f->mean_m, t->mean_m).c_str(), b->mean_m * 1e3,
              gainPercent(b->mean_m, t->mean_m).c_str(), seconds * 1e3);
  return true;
}

bool report(const std::string& title, const BodyModel& model) {
  std::printf("\n%s: %d vertices, %d joints (held-out: %d poses)\n\n", title.c_str(),
              model.numVertices(), model.numJoints(), held_out_poses);
  std::printf(
      "| M | truncated mean mm | truncated max mm | optimized mean mm | optimized max mm | mean "
      "gain | bound mean mm | bound gain | fit ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  bool ok = true;
  for (int m : {1, 2, 4, 8})
    if (m <= model.numJoints()) ok = reportRow(model, m) && ok;
  return ok;
}

}  // namespace
}  // namespace smpl

namespace {
constexpr const char* kUsage =
    "Usage: smpl-skin-report [--poses N] [MODEL ...]\n"
    "Held-out skin error of truncated vs fitted weights (N = 1, 2, 4, 8 influences) for the\n"
    "built-in body, then each model file (.npz or .pkl); N held-out poses (default 32).\n";
}  // namespace

int main(int argc, char** argv) {
  using namespace smpl;
  // --help anywhere prints the usage; any other dash argument but a leading
  // --poses N is an unknown option (never read as a model path).
  const bool poses = argc > 2 && std::string(argv[1]) == "--poses";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") return std::printf("%s", kUsage), 0;
    if (arg.size() > 1 && arg[0] == '-' && !(poses && i <= 2))
      return std::fprintf(stderr, "Error in arguments: unknown option '%s'\n%s", arg.c_str(),
                          kUsage),
             1;
  }
  int first = 1;
  if (poses) {
    held_out_poses = std::atoi(argv[2]);
    first = 3;
    if (held_out_poses < 1) return std::fprintf(stderr, "--poses: expected N >= 1\n"), 1;
  }
  bool ok = report("builtin", demoBody());
  for (int i = first; i < argc; ++i) {
    Result<BodyModel> model = loadModel(argv[i]);
    if (!model) {
      std::fprintf(stderr, "Error loading %s\n", model.message().c_str());
      return 2;
    }
    ok = report(argv[i], *model) && ok;
  }
  return ok ? 0 : 3;
}
