// What pruning skin weights to M influences costs: vertex error of the model
// posed with pruned weights against the same model with all its weights, over
// a fixed set of random poses (deterministic seed), correctives included.
#pragma once

#include "core/body_model.h"
#include "core/result.h"
#include "exporter/pipeline.h"

namespace smpl {

struct PruningError {
  double mean_m = 0.0;  // mean over poses and vertices, metres
  double max_m = 0.0;   // worst vertex over all poses
  int poses = 0;
};

Result<PruningError> measurePruningError(const BodyModel& model, const ExportOptions& options, int poses);

}  // namespace smpl
