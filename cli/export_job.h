// One export: model + settings + motions -> one output file and its sidecar,
// written atomically. Shared by the single-file CLI and the batch runner.
#pragma once

#include <string>
#include <vector>

#include "cli/exit_code.h"
#include "cli/settings.h"
#include "core/body_model.h"
#include "core/math/skin_weights.h"
#include "core/result.h"

namespace smpl {

struct ExportJob {
  std::string out;
  std::vector<std::string> motions;
  bool progress = false;      // draw a progress bar on stderr while baking
  std::string producer_hash;  // recorded in the sidecar; "" = computed here (producer.h)
};

struct ExportReport {
  size_t bytes = 0;
  double seconds = 0.0;
  int vertices = 0, joints = 0, morph_targets = 0, max_influences = 0;
  int frames = 0;                  // total animation frames written
  std::vector<std::string> notes;  // e.g. motion joints dropped by the mapping
  ExportOptions options;           // as used (betas may come from the motion)
  SparseSkin skin;  // the skin written, per model vertex (exporter/pruning_error.h skinOfAsset)
};

// "Error <verb> <path>: <reason>", without repeating the path when the reason
// already starts with it (core errors name their file). One printable line
// (core/io/printable.h) of at most 4 KiB: a path over 1 KiB is shortened in
// its middle wherever it appears, and the reason at the end is always kept
// ("Error saving /data/aaaa...aaaa/x.glb: cannot create: File name too long").
std::string errorLine(const std::string& verb, const std::string& path, const std::string& message);

// Returns the report, or an error whose message is the whole line for the
// user ("Error loading walk.npz: ...") and whose kind gives the exit code
// (cli/exit_code.h). Before any
// work, stale temporaries of this output and its sidecar are removed
// (file_io.h; unless the job comes from planBatch, which removed them for
// every output: job.producer_hash set); after building, the asset must pass validateAsset (exit 3,
// nothing written); the output and its sidecar are committed together
// (writeFilesTogether, sidecar last): both new or both as before.
Result<ExportReport> runExport(const BodyModel& model, const Settings& settings,
                               const ExportJob& job);

}  // namespace smpl
