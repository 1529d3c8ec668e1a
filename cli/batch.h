// Batch conversion (--motion-dir DIR --out-dir DIR): every .npz/.json motion
// in DIR becomes <out-dir>/<stem>.<format>, on all cores. Outputs newer than
// their motion and model are skipped; a failing file is reported and the
// batch goes on.
#pragma once

#include "core/body_model.h"
#include "cli/model_source.h"
#include "cli/settings.h"

namespace smpl {

struct BatchSummary {
  int converted = 0, skipped = 0, failed = 0;
};

// `models` gives each motion its model (one file, or per motion from a folder).
BatchSummary runBatch(ModelSource& models, const Settings& settings);

}  // namespace smpl
