// Batch conversion (--motion-dir DIR --out-dir DIR): every .npz/.json/.smpl/
// .pkl motion in DIR becomes <out-dir>/<stem>.<format>, on all cores.
// planBatch (batch_plan.h) decides before any work what to convert and what is
// up to date (same inputs and options), and keeps this run's --shard share
// (cli/batch_shard.h). Files without pose keys (AMASS shape.npz,
// *_stagei.npz: hasPoseData() is false, decided from the keys, not the name)
// are skipped with a note naming them and do not count as failed; a failing
// file (it has pose keys but is broken) is reported and the batch goes on.
// --manifest writes cli/manifest.h's JSON lines.
#pragma once

#include "cli/batch_plan.h"
#include "cli/settings.h"
#include "request/model_source.h"
#include "request/run_request.h"

namespace smpl {

struct BatchSummary {
  int converted = 0, skipped = 0, failed = 0;  // skipped: up to date
  int no_poses = 0;                            // skipped: no pose data
  bool manifest_failed = false;                // --manifest could not be written
};

// Converts `plan` (from planBatch with the same settings): one export job per
// output (request/run_request.h runExportJob, the settings' request
// with that output and motion), sharing `inputs` (loadRunInputs) and
// `models` (one file, or per motion from a folder). Prints the plan's notes
// and per-entry errors (counted as failed) and one line per output.
BatchSummary runBatch(ModelSource& models, const Settings& settings, const BatchPlan& plan,
                      const RunInputs& inputs);

}  // namespace smpl
