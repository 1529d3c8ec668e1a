// What reducing skin weights to M influences costs: vertex error of the model
// posed with the exported weights (exporter/export_skin.h) against the same
// model with all its weights, over a fixed set of random poses (seed 20261124,
// which the weight fit never trains on: held-out poses), correctives
// included. The truncated weights are measured on the same poses, so the
// summary can show what the fit gains.
#pragma once

#include "core/body_model.h"
#include "core/math/skin_weights.h"
#include "core/result.h"
#include "exporter/asset.h"
#include "exporter/pipeline.h"

namespace smpl {

struct SkinError {
  double mean_m = 0.0;  // mean over poses and vertices, metres
  double max_m = 0.0;   // worst vertex over all poses, metres
};

struct PruningError {
  double mean_m = 0.0;  // the exported weights (options.skin_weights): mean, metres
  double max_m = 0.0;   // worst vertex over all poses, metres
  SkinError truncated;  // the M largest weights renormalised, same poses
  int influences = 0;   // M
  int poses = 0;
};

// Held-out error of `options`' skin (and of truncation) over `poses` poses.
// `exported`: the skin the export wrote (model vertices, see skinOfAsset), so
// the weights are not fitted a second time; null: computed here (exportSkin).
Result<PruningError> measurePruningError(const BodyModel& model, const ExportOptions& options,
                                         int poses, const SparseSkin* exported = nullptr);

// The skin an asset carries, per model vertex (N x M; asset vertices split at
// UV seams share their model vertex's weights): float weights widened.
SparseSkin skinOfAsset(const SkinnedMesh& mesh, int num_vertices);

// Held-out error of one N x K dense weight matrix over `poses` poses (seed 20261124).
Result<SkinError> measureSkinError(const BodyModel& model, const ExportOptions& options,
                                   const Eigen::MatrixXd& weights, int poses);

}  // namespace smpl
