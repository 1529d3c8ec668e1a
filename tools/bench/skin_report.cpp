// smpl-skin-report: what fitted skin weights (--skin-weights optimized,
// core/math/skin_weight_fit.h) and the corrective refit (--corrective-refit,
// core/math/corrective_refit.h) gain over truncation, per model: the held-out
// vertex error against the unpruned model (exporter/pruning_error.h) of
// truncated weights, optimised weights with the model's correctives, and
// optimised weights with refitted correctives (the default export), for
// M = 1, 2, 4, 8 influences (mean and max, mm), and the time the fit and the
// refit take. Pose sets, none used for training: "random" (uniform +-0.6
// rad, seed 20261124), "motion" (motion-like, core/math/motion_poses.h, seed
// 20261125) and, with --motion FILE, the frames of a real motion (every
// --stride-th frame), mapped onto each model's joints by joint name (joints
// the motion does not have stay at rest; MANO's unsided names take the
// motion's right hand). "bound": the weight fit trained on
// the random held-out poses themselves (no prior, no guard, every support
// subset it can afford, summed distance minimised): a lower bound on the
// random-pose mean any weights with such supports reach (weights only).
//   smpl-skin-report [--poses N] [--motion FILE] [--stride S] [MODEL ...]
//       the built-in body, then each model file; N held-out poses per
//       synthetic set (default 32); S: every S-th motion frame (default 10)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"
#include "core/joint_names.h"
#include "core/math/corrective_refit.h"
#include "core/math/skin_weight_fit.h"
#include "core/math/skin_weights.h"
#include "core/models/model_loader.h"
#include "core/motions/motion.h"
#include "exporter/export_skin.h"
#include "exporter/pruning_error.h"

namespace smpl {
namespace {

int held_out_poses = 32;                     // --poses
constexpr uint64_t kHeldOutSeed = 20261124;  // exporter/pruning_error.h's random poses
std::string motion_path;                     // --motion
int motion_stride = 10;                      // --stride

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The fit trained on the held-out poses themselves (see the file comment).
SparseSkin boundSkin(const BodyModel& model, const ShapedBody& body, int m) {
  SkinFitOptions o;
  o.max_influences = m;
  o.training_poses = held_out_poses;
  o.seed = kHeldOutSeed;
  o.motion_like = false;
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

// The real motion's frames on `model`'s joints, by joint name.
Result<std::vector<Rotations>> motionFrames(const BodyModel& model) {
  Result<Motion> motion = loadMotion(motion_path);
  if (!motion) return motion.error();
  const std::vector<std::string>& names = canonicalJointNames(motion->layout);
  std::vector<int> source(size_t(model.numJoints()), -1);
  for (int k = 0; k < model.numJoints(); ++k) {
    const std::string name = canonicalJointName(model.joint_names[size_t(k)]);
    for (size_t j = 0; j < names.size(); ++j)
      if (name == names[j]) source[size_t(k)] = int(j);
    for (size_t j = 0; j < names.size() && source[size_t(k)] < 0; ++j)
      if ("right_" + name == names[j]) source[size_t(k)] = int(j);  // MANO: a right hand
  }
  std::vector<Rotations> frames;
  for (size_t t = 0; t < motion->frames.size(); t += size_t(motion_stride)) {
    Rotations r(size_t(model.numJoints()), Eigen::Matrix3d::Identity());
    for (int k = 0; k < model.numJoints(); ++k)
      if (source[size_t(k)] >= 0 && size_t(source[size_t(k)]) < motion->frames[t].size())
        r[size_t(k)] = motion->frames[t][size_t(source[size_t(k)])];
    frames.push_back(r);
  }
  return frames;
}

struct Skins {
  SparseSkin truncated, fitted, bound;
  CorrectiveRefit refit;
  double fit_ms = 0.0, refit_ms = 0.0;
};

Skins skinsFor(const BodyModel& model, const ShapedBody& body, int m) {
  Skins s;
  ExportOptions o;
  o.max_influences = m;
  s.truncated = pruneWeights(model.weights, m);
  auto start = std::chrono::steady_clock::now();
  s.fitted = exportSkin(model, body, o);
  s.fit_ms = secondsSince(start) * 1e3;
  start = std::chrono::steady_clock::now();
  s.refit = refitCorrectives(model, body, s.fitted, CorrectiveRefitOptions());
  s.refit_ms = secondsSince(start) * 1e3;
  s.bound = boundSkin(model, body, m);
  return s;
}

// One row: M, truncated / optimized / optimized + refit mean and max, the
// refit's mean and max gain over truncation, bound (random set), times.
bool reportRow(const BodyModel& model, const ShapedBody& body, const Skins& s, int m,
               const std::vector<Rotations>& frames, bool bound) {
  const ExportOptions o;
  Result<SkinError> t = measureSkinOn(model, o, s.truncated, nullptr, frames);
  Result<SkinError> f = measureSkinOn(model, o, s.fitted, nullptr, frames);
  Result<SkinError> r = measureSkinOn(model, o, s.fitted, &s.refit, frames);
  Result<SkinError> b = bound ? measureSkinOn(model, o, s.bound, nullptr, frames) : t;
  for (const Result<SkinError>* e : {&t, &f, &r, &b})
    if (!*e) return std::printf("  %s\n", e->message().c_str()), false;
  std::printf(
      "| %d | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %s | %s | %s | %s | %.0f | %.0f |\n", m,
      t->mean_m * 1e3, t->max_m * 1e3, f->mean_m * 1e3, f->max_m * 1e3, r->mean_m * 1e3,
      r->max_m * 1e3, gainPercent(r->mean_m, t->mean_m).c_str(),
      gainPercent(r->max_m, t->max_m).c_str(), gainPercent(f->mean_m, t->mean_m).c_str(),
      bound ? gainPercent(b->mean_m, t->mean_m).c_str() : "", s.fit_ms, s.refit_ms);
  (void)body;
  return true;
}

bool report(const std::string& title, const BodyModel& model) {
  const Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  if (!body) return std::printf("  %s\n", body.message().c_str()), false;
  std::vector<std::pair<std::string, std::vector<Rotations>>> sets = {
      {"random", heldOutFrames(model, held_out_poses, false)},
      {"motion", heldOutFrames(model, held_out_poses, true)}};
  if (!motion_path.empty()) {
    Result<std::vector<Rotations>> real = motionFrames(model);
    if (!real) return std::fprintf(stderr, "%s\n", real.message().c_str()), false;
    sets.push_back({"real " + motion_path, *real});
  }
  std::vector<std::pair<int, Skins>> skins;
  for (int m : {1, 2, 4, 8})
    if (m <= model.numJoints()) skins.push_back({m, skinsFor(model, *body, m)});
  bool ok = true;
  for (const auto& set : sets) {
    std::printf("\n%s: %d vertices, %d joints; held-out %s poses: %zu\n\n", title.c_str(),
                model.numVertices(), model.numJoints(), set.first.c_str(), set.second.size());
    std::printf(
        "| M | truncated mean mm | truncated max mm | optimized mean mm | optimized max mm | "
        "refit mean mm | refit max mm | refit mean gain | refit max gain | optimized mean gain | "
        "bound gain | fit ms | refit ms |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& [m, s] : skins)
      ok = reportRow(model, *body, s, m, set.second, set.first == "random") && ok;
  }
  return ok;
}

}  // namespace
}  // namespace smpl

namespace {
constexpr const char* kUsage =
    "Usage: smpl-skin-report [--poses N] [--motion FILE [--stride S]] [MODEL ...]\n"
    "Held-out skin error of truncated vs fitted weights, with and without the corrective refit\n"
    "(N = 1, 2, 4, 8 influences) for the built-in body, then each model file (.npz or .pkl);\n"
    "N held-out poses (default 32); --motion: also the frames of a motion (every S-th).\n";

bool isFlag(const std::string& a) { return a == "--poses" || a == "--stride" || a == "--motion"; }
}  // namespace

int main(int argc, char** argv) {
  using namespace smpl;
  // --help anywhere prints the usage; leading --poses/--motion/--stride take a
  // value; any other dash argument is an unknown option (never a model path).
  int first = 1;
  while (first + 1 < argc && isFlag(argv[first])) first += 2;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") return std::printf("%s", kUsage), 0;
    const bool value_of_flag = i < first && (i - 1) % 2 == 1;
    if (arg.size() > 1 && arg[0] == '-' && !value_of_flag && !(i < first && isFlag(arg)))
      return std::fprintf(stderr, "Error in arguments: unknown option '%s'\n%s", arg.c_str(),
                          kUsage),
             1;
  }
  for (int i = 1; i + 1 < first; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--poses") {
      held_out_poses = std::atoi(value.c_str());
      if (held_out_poses < 1) return std::fprintf(stderr, "--poses: expected N >= 1\n"), 1;
    } else if (flag == "--stride") {
      motion_stride = std::atoi(value.c_str());
      if (motion_stride < 1) return std::fprintf(stderr, "--stride: expected S >= 1\n"), 1;
    } else {
      motion_path = value;
    }
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
