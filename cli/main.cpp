// smpl-export: a thin main. Parse and check every option, load the model,
// then run one export (or a batch); print a summary. Everything the run reads
// or builds is charged to one memory budget (core/memory_budget.h, set by
// --memory-limit); exceptions that still escape (std::bad_alloc, filesystem
// errors) are caught here as a last resort and reported as one error line with
// the exit code of the stage that failed, never as an abort.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>

#include "cli/batch.h"
#include "cli/batch_plan.h"
#include "cli/betas_file.h"
#include "cli/export_job.h"
#include "cli/model_source.h"
#include "cli/options.h"
#include "cli/output_guard.h"
#include "cli/settings.h"
#include "core/io/printable.h"
#include "core/load/validate_inputs.h"
#include "core/memory_budget.h"
#include "exporter/export_skin.h"
#include "exporter/pruning_error.h"

using namespace smpl;

namespace {

// What main is doing, for the last-resort error line.
struct Stage {
  const char* verb = "in";
  std::string path = "arguments";
  ExitCode code = kExitUsage;
  void set(const char* v, const std::string& p, ExitCode c) { verb = v, path = p, code = c; }
};

// One printable line; a line over 4 KiB loses its middle, never its reason.
int report(const std::string& line, int code) {
  std::fprintf(stderr, "%s\n", printableMiddle(line, 4096).c_str());
  return code;
}

// The summary must not be lost silently (`> /dev/full`, a closed pipe's
// buffer): stdout is flushed before exit and a write error is a write error
// (exit 4, one line on stderr), unless the run already failed.
int finishStdout(int code) {
  errno = 0;
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
  const std::string reason = errno != 0 ? std::strerror(errno) : "write error";
  report("Error writing standard output: " + reason, kExitSave);
  return code == kExitOk ? kExitSave : code;
}

void printSummary(const std::string& out, const ExportReport& r, const PruningError& err) {
  std::printf("%s: %d vertices, %d joints, %d morph targets, %.2f MB, %.0f ms\n",
              printable(out).c_str(), r.vertices, r.joints, r.morph_targets, r.bytes / 1e6,
              r.seconds * 1e3);
  if (r.frames > 0) std::printf("animation: %d frames\n", r.frames);
  for (const std::string& note : r.notes) std::printf("note: %s\n", printable(note, 4096).c_str());
  std::printf(
      "skinning error of %d influences vs all (%d held-out random poses): %s mean %.3f mm, max "
      "%.3f mm",
      r.max_influences, err.poses, skinWeightMethodName(r.options.skin_weights), err.mean_m * 1e3,
      err.max_m * 1e3);
  if (r.options.skin_weights != SkinWeightMethod::Truncated)
    std::printf("; truncated mean %.3f mm, max %.3f mm", err.truncated.mean_m * 1e3,
                err.truncated.max_m * 1e3);
  std::printf("\n");
}

int run(int argc, char** argv, Stage* stage) {
  Result<Settings> parsed = parseSettings(argc, argv);
  if (!parsed) return report("Error in arguments: " + parsed.message(), exitCodeFor(parsed.kind()));
  Settings& s = *parsed;
  if (s.help) return std::printf("%s", usageText().c_str()), kExitOk;
  if (s.version) return std::printf("smpl-export %s\n", SMPL_EXPORT_VERSION), kExitOk;
  setMemoryLimit(s.memory_limit);

  // Before any work: outputs must not be inputs; a batch is planned (motion
  // listing, name collisions, up-to-date decisions) and refused as a whole.
  Result<BatchPlan> plan = BatchPlan();
  if (!s.motion_dir.empty())
    plan = planBatch(s);
  else if (Status st = checkOutputsAreNotInputs(outputsOf(s, s.out), runInputs(s, s.motions)); !st)
    plan = makeError("Error in arguments: " + st.message(), ErrorKind::Usage);
  if (!plan) return report(plan.message(), exitCodeFor(plan.kind()));

  if (!s.betas_file.empty()) {
    stage->set("loading", s.betas_file, kExitLoad);
    std::string note;  // per-frame (T,B) betas that differ: their mean, with a note
    Result<std::vector<double>> betas = readBetasFile(s.betas_file, &note);
    if (betas) {
      if (Status st = checkCoefficients(*betas, s.betas_file, "'betas'"); !st) betas = st.error();
    }
    if (!betas) return report(errorLine("loading", s.betas_file, betas.message()), kExitLoad);
    if (!note.empty() && !s.quiet)
      std::printf("note: %s: %s\n", printable(s.betas_file).c_str(), note.c_str());
    s.export_options.betas = *betas;
  }
  stage->set("loading", s.model, kExitLoad);
  ModelSource models(s.model);  // a file, builtin, or a folder (picked per motion: kind and gender)
  if (!s.motion_dir.empty()) {
    if (!models.isFolder()) {  // one model for the whole batch: load it before any motion
      Result<ModelPick> one = models.forMotion("");
      if (!one) return report(errorLine("loading", s.model, one.message()), kExitLoad);
    }
    stage->set("exporting", s.motion_dir, kExitExport);
    BatchSummary summary = runBatch(models, s, *plan);
    if (summary.manifest_failed) return kExitSave;
    return summary.failed > 0 ? kExitExport : kExitOk;
  }
  Result<ModelPick> pick = models.forMotion(s.motions.empty() ? "" : s.motions[0]);
  if (!pick) return report(errorLine("loading", s.model, pick.message()), kExitLoad);
  if (!pick->note.empty() && !s.quiet)
    std::printf("note: %s\n", printable(pick->note, 4096).c_str());
  const BodyModel& loaded = *pick->model;
  stage->set("exporting", s.out, kExitExport);
  Result<ExportReport> result =
      runExport(loaded, s, ExportJob{s.out, s.motions, isatty(2) != 0 && !s.quiet, ""});
  if (!result) return report(result.message(), exitCodeFor(result.kind()));
  if (!s.quiet) {
    Result<PruningError> err =
        measurePruningError(loaded, result->options, s.error_poses, &result->skin);
    if (!err) return report("Error measuring " + s.out + ": " + err.message(), kExitExport);
    printSummary(s.out, *result, *err);
    std::printf("model: %s\n", printable(pick->path).c_str());
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Stage stage;
  try {
    return finishStdout(run(argc, argv, &stage));
  } catch (const std::bad_alloc&) {
    return report("Error " + std::string(stage.verb) + " " + stage.path +
                      ": out of memory (the system refused an allocation below --memory-limit " +
                      formatBytes(memoryLimit()) + "; set a lower limit)",
                  stage.code);
  } catch (const std::filesystem::filesystem_error& e) {
    return report("Error " + std::string(stage.verb) + " " + stage.path + ": " + e.what(),
                  stage.code);
  } catch (const std::exception& e) {
    return report(
        "Error " + std::string(stage.verb) + " " + stage.path + ": internal error: " + e.what(),
        stage.code);
  } catch (...) {
    return report("Error " + std::string(stage.verb) + " " + stage.path + ": internal error",
                  stage.code);
  }
}
