// Batch conversion (--motion-dir DIR --out-dir DIR): every .npz/.json motion
// in DIR becomes <out-dir>/<stem>.<format>, on all cores. Outputs newer than
// their motion and model are skipped; a failing file is reported and the
// batch goes on.
#pragma once

#include "core/body_model.h"
#include "cli/settings.h"

namespace smpl {

struct BatchSummary {
  int converted = 0, skipped = 0, failed = 0;
};

BatchSummary runBatch(const BodyModel& model, const Settings& settings);

}  // namespace smpl
