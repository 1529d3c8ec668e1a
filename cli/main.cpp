// smpl-export: a thin main. Parse and check every option, load the model,
// then run one export (or a batch); print a summary.
#include <unistd.h>

#include <cstdio>
#include <string>

#include "cli/batch.h"
#include "cli/export_job.h"
#include "cli/model_source.h"
#include "exporter/pruning_error.h"
#include "cli/settings.h"

using namespace smpl;

namespace {

void printSummary(const std::string& out, const ExportReport& r, const PruningError& err) {
  std::printf("%s: %d vertices, %d joints, %d morph targets, %.2f MB, %.0f ms\n", out.c_str(), r.vertices, r.joints,
              r.morph_targets, r.bytes / 1e6, r.seconds * 1e3);
  if (r.frames > 0) std::printf("animation: %d frames\n", r.frames);
  for (const std::string& note : r.notes) std::printf("note: %s\n", note.c_str());
  std::printf("skinning error of %d influences vs all (%d random poses): mean %.3f mm, max %.3f mm\n",
              r.max_influences, err.poses, err.mean_m * 1e3, err.max_m * 1e3);
}

}  // namespace

int main(int argc, char** argv) {
  Result<Settings> parsed = parseSettings(argc, argv);
  if (!parsed) return std::fprintf(stderr, "Error in arguments: %s\n", parsed.message().c_str()), kExitUsage;
  Settings& s = *parsed;
  if (s.help) return std::printf("%s", usageText().c_str()), kExitOk;
  if (s.version) return std::printf("smpl-export %s\n", SMPL_EXPORT_VERSION), kExitOk;

  if (!s.betas_file.empty()) {
    std::string note;
    Result<std::vector<double>> betas = readBetasFile(s.betas_file, &note);
    if (!betas) return std::fprintf(stderr, "%s\n", errorLine("loading", s.betas_file, betas.message()).c_str()), kExitLoad;
    if (!note.empty() && !s.quiet) std::printf("note: %s: %s\n", s.betas_file.c_str(), note.c_str());
    s.export_options.betas = *betas;
  }
  ModelSource models(s.model);  // a file, builtin, or a folder (picked per motion)
  if (!s.motion_dir.empty() && !models.isFolder()) {  // one model for the whole batch: load it first
    Result<ModelPick> one = models.forMotion("");
    if (!one) return std::fprintf(stderr, "%s\n", errorLine("loading", s.model, one.message()).c_str()), kExitLoad;
  }
  if (!s.motion_dir.empty()) {
    BatchSummary summary = runBatch(models, s);
    return summary.failed > 0 ? kExitExport : kExitOk;
  }
  Result<ModelPick> pick = models.forMotion(s.motions.empty() ? "" : s.motions[0]);
  if (!pick) return std::fprintf(stderr, "%s\n", errorLine("loading", s.model, pick.message()).c_str()), kExitLoad;
  const BodyModel* loaded = pick->model;
  if (!pick->note.empty() && !s.quiet) std::printf("note: %s\n", pick->note.c_str());
  JobFailure failure{kExitOk, ""};
  Result<ExportReport> report = runExport(*loaded, s, ExportJob{s.out, s.motions, isatty(2) != 0 && !s.quiet}, &failure);
  if (!report) return std::fprintf(stderr, "%s\n", failure.message.c_str()), failure.code;
  if (!s.quiet) {
    Result<PruningError> err = measurePruningError(*loaded, report->options, s.error_poses);
    if (!err) return std::fprintf(stderr, "Error measuring %s: %s\n", s.out.c_str(), err.message().c_str()), kExitExport;
    printSummary(s.out, *report, *err);
    std::printf("model: %s\n", pick->path.c_str());
  }
  return kExitOk;
}
