// runCommandLine: see command_line.h.
#include "cli/command_line.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <new>
#include <string>
#include <thread>

#include "cli/batch.h"
#include "cli/batch_plan.h"
#include "cli/exit_code.h"
#include "cli/options.h"
#include "cli/settings.h"
#include "cli/summary.h"
#include "core/io/printable.h"
#include "core/math/simd_target.h"
#include "core/memory_budget.h"
#include "core/os/system.h"
#include "core/parallel.h"
#include "exporter/skin_cache.h"
#include "request/run_request.h"

namespace smpl {
namespace {

constexpr int kSkinErrorPoses = 32;  // held-out random poses of the summary's skinning error

// What the run is doing, for the last-resort error line.
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

// Batch mode: the checks, then the plan and its path guard before any work,
// the inputs every job shares, then the jobs.
int runBatchMode(const Settings& s, ModelSource* models, Stage* stage) {
  if (Status st = beginRun(s.request); !st) return report(st.message(), exitCodeFor(st.kind()));
  Result<BatchPlan> plan = planBatch(s);
  if (!plan) return report(plan.message(), exitCodeFor(plan.kind()));
  Result<RunInputs> inputs = loadRunInputs(s.request, models);
  if (!inputs) return report(inputs.message(), exitCodeFor(inputs.kind()));
  // The motions of one subject fit once: one subject per worker in flight, and the next.
  const unsigned workers =
      s.request.writer.threads ? unsigned(*s.request.writer.threads) : hardwareThreads();
  inputs->skins = std::make_shared<SkinCache>(std::max(2u, workers + 1));
  if (!inputs->betas_note.empty() && !s.quiet)
    std::fprintf(stderr, "note: %s\n", inputs->betas_note.c_str());
  stage->set("exporting", s.request.motion_dir, kExitExport);
  BatchSummary summary = runBatch(*models, s, *plan, *inputs);
  if (summary.manifest_failed) return kExitSave;
  return summary.failed > 0 ? kExitExport : kExitOk;
}

int run(int argc, char** argv, Stage* stage) {
  Result<Settings> parsed = parseSettings(argc, argv);
  if (!parsed) return report("Error in arguments: " + parsed.message(), exitCodeFor(parsed.kind()));
  Settings& s = *parsed;
  // SMPL_EXPORT_SIMD forces the kernels' instruction set (the output is the same bytes).
  if (Status st = useSimdTargetFromEnvironment(); !st)
    return report("Error in environment: " + st.message(), kExitUsage);
  if (s.help) return std::printf("%s", usageText().c_str()), kExitOk;
  if (s.version) return std::printf("smpl-export %s\n", SMPL_EXPORT_VERSION), kExitOk;
  ModelSource models(s.request.model);  // a file, builtin, or a folder (picked per motion)
  if (isBatch(s)) return runBatchMode(s, &models, stage);
  ExportRequest& request = s.request;
  if (os::isTerminal(2) && !s.quiet) request.progress = drawProgress;
  if (!s.quiet) request.skin_error_poses = kSkinErrorPoses;
  stage->set("exporting", request.out, kExitExport);
  if (request.scene) {  // every person in one output
    Result<ExportReport> result = runSceneExport(request, &models);
    if (!result) return report(result.message(), exitCodeFor(result.kind()));
    printNotes(*result, s.quiet);
    if (!s.quiet) printSummary(request.out, *result);
    return kExitOk;
  }
  if (request.track.kind == TrackChoice::Kind::All) {  // one output per person
    Result<std::vector<ExportReport>> results = runTrackExports(request, &models);
    if (!results) return report(results.message(), exitCodeFor(results.kind()));
    for (const ExportReport& r : *results) {
      printNotes(r, s.quiet);
      if (!s.quiet) printSummary(r.out, r);
    }
    return kExitOk;
  }
  Result<ExportReport> result = runExportRequest(request, &models);
  if (!result) return report(result.message(), exitCodeFor(result.kind()));
  printNotes(*result, s.quiet);
  if (!s.quiet) printSummary(request.out, *result);
  return kExitOk;
}

}  // namespace

int runCommandLine(int argc, char** argv) {
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

}  // namespace smpl
