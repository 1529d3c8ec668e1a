// Batch conversion (--motion-dir DIR --out-dir DIR): every .npz/.json motion
// in DIR becomes <out-dir>/<stem>.<format>, on all cores. planBatch
// (batch_plan.h) decides before any work what to convert and what is up to
// date (same inputs and options); a failing file is reported and the batch
// goes on.
#pragma once

#include "core/body_model.h"
#include "cli/batch_plan.h"
#include "cli/model_source.h"
#include "cli/settings.h"

namespace smpl {

struct BatchSummary {
  int converted = 0, skipped = 0, failed = 0;
};

// Converts `plan` (from planBatch with the same settings); prints its notes
// and per-entry errors (counted as failed) and one line per output. `models`
// gives each motion its model (one file, or per motion from a folder).
BatchSummary runBatch(ModelSource& models, const Settings& settings, const BatchPlan& plan);

}  // namespace smpl
