// Running an export request (export_request.h), in the layers' order and
// never back up: check the request once (check_request.h), guard every path
// the run touches (run_paths.h), load the inputs (the betas file once, the
// model through the ModelSource, each motion decoded once and reused for the
// model-folder pick, the fit hands, the betas and DMPL), check what depends on
// the model, build the finished asset (exportAsset: bake, fold, validate),
// serialise it with the output's writer (writers/writer.h) and commit the
// output, its buffer and its sidecar together (writeFilesTogether).
//
//   ModelSource models(request.model);
//   Result<ExportReport> report = runExportRequest(request, &models);
//
// A batch (cli/batch.cpp) runs the same steps split up: beginRun, its own
// plan and guard over every output (cli/batch_plan.cpp), loadRunInputs once,
// then runExportJob per output on worker threads.
//
// Every error is the whole line for the user ("Error loading walk.npz: ...",
// error_line.h) and its kind gives the exit code (cli/exit_code.h): Usage 1,
// Load 2, Export 3, Write 4. Exceptions that still escape (std::bad_alloc
// below --memory-limit, filesystem errors) become such a line for the stage
// that was running, never an abort: loading the betas file or a model
// ("Error loading m.npz: out of memory ...", exit 2), anything else of an
// export job, its motions included ("Error exporting o.glb: ...", exit 3).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "exporter/skin_cache.h"
#include "request/export_request.h"
#include "request/model_source.h"

namespace smpl {

// What the exports of one run share, read once before any motion.
struct RunInputs {
  std::vector<double> betas;  // --betas, or the values of --betas-file
  bool betas_given = false;   // --betas or --betas-file: the motions' betas are not used
  std::string betas_note;     // "<file>: <per-frame rows averaged ...>" or ""
  // The fitted skins of the run's subjects: a batch's motions of one subject
  // (same model, betas, skin options) fit once (exporter/skin_cache.h). Set
  // by batch mode; null for one export (a cache would only copy its fit).
  std::shared_ptr<SkinCache> skins;
};

// checkRequest, then the process's memory budget (--memory-limit,
// core/memory_budget.h). Errors: "Error in arguments: ..." (Usage).
Status beginRun(const ExportRequest& request);

// --betas-file read once (core/models/betas_file.h), then a model file (not a
// folder, whose pick needs a motion) loaded into `models` before any motion.
// Errors: "Error loading <file>: ..." (Load).
Result<RunInputs> loadRunInputs(const ExportRequest& request, ModelSource* models);

// One output from `request.motions` (no guard: the caller ran it): stale
// temporaries of the output removed (request.clean_temporaries), the
// motions decoded, the model picked, checkRequestForModel, the asset built
// and validated (exit 3, nothing written), the output and its sidecar
// committed together (writeFilesTogether, sidecar last: both new or both as
// before), and with request.skin_error_poses > 0 the held-out skinning error
// measured (exporter/pruning_error.h).
Result<ExportReport> runExportJob(const ExportRequest& request, const RunInputs& inputs,
                                  ModelSource* models);

// --track all: the one motion decoded once, one export per track to
// <out stem>.track<ID>.<ext> (request_motions.h trackOutput; a file with one
// person: `out` itself), every output guarded before the first is written.
Result<std::vector<ExportReport>> runTrackExports(const ExportRequest& request,
                                                  ModelSource* models);

// --scene: every track of the one motion (decoded once) a skinned body of
// one file, each built as a one-body export builds it under the name
// <--name>_<track id> (exporter/scene_timeline.h composeScene: the shared
// timeline, hidden outside its frames; the file's camera when it has one);
// written with its sidecar as one export is. Errors as runExportRequest; a
// format that cannot hold a scene is refused by checkRequest.
Result<ExportReport> runSceneExport(const ExportRequest& request, ModelSource* models);

// One export: beginRun, checkRunPaths(runPaths(request, {out}, motions))
// before any work, loadRunInputs, runExportJob.
Result<ExportReport> runExportRequest(const ExportRequest& request, ModelSource* models);

// Exports whose first motions are already decoded (the Python module,
// python/: motions read from memory or read once and exported many times):
// `motions[i]` is the decoded request.motions[i] (which names it in errors,
// notes and the producer hash); the request's other motions are read as
// runExportRequest reads them. Otherwise the same steps and errors.
//
// exportToMemory keeps the output instead of writing it: request.out names
// the format only (its extension), no path is guarded or written and no
// sidecar is made (it describes files on disk); `bytes` are the bytes the
// CLI writes to request.out. A .gltf needs --gltf-embed (its buffer is a
// second file). Usage error (exit 1): a .gltf without it.
struct ExportedBytes {
  std::string bytes;
  ExportReport report;
};
Result<ExportedBytes> exportToMemory(const ExportRequest& request, std::vector<Motion> motions,
                                     ModelSource* models);

// The same, written as runExportRequest writes it (path guard, output and
// sidecar committed together).
Result<ExportReport> exportDecoded(const ExportRequest& request, std::vector<Motion> motions,
                                   ModelSource* models);

}  // namespace smpl
