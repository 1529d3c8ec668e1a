// What reducing skin weights to M influences costs: vertex error of the model
// posed with the exported weights (exporter/export_skin.h) against the same
// model with all its weights, over a fixed set of random poses (seed 20261124,
// which the weight fit never trains on: held-out poses), correctives
// included. With the corrective refit (ExportOptions::corrective_refit,
// core/math/corrective_refit.h) the exported skin is measured with the
// refitted correctives it was written with, and also without them; the
// truncated weights with the model's correctives are measured on the same
// poses, so the summary can show what the fit and the refit gain. Motion-like
// held-out poses (core/math/motion_poses.h, seed 20261125) are a second set
// for reports (smpl-skin-report); neither seed trains anything.
#pragma once

#include "core/body_model.h"
#include "core/math/corrective_refit.h"
#include "core/math/forward.h"
#include "core/math/skin_weights.h"
#include "core/result.h"
#include "exporter/asset.h"
#include "exporter/export_options.h"

namespace smpl {

struct SkinError {
  double mean_m = 0.0;  // mean over poses and vertices, metres
  double max_m = 0.0;   // worst vertex over all poses, metres
};

struct PruningError {
  double mean_m = 0.0;      // the export (options.skin_weights, refit if any): mean, metres
  double max_m = 0.0;       // worst vertex over all poses, metres
  SkinError truncated;      // the M largest weights renormalised, the model's correctives
  bool refit = false;       // the correctives were refitted (then: without_refit)
  SkinError without_refit;  // the exported weights with the model's correctives
  int influences = 0;       // M
  int poses = 0;
};

// Held-out error of `options`' skin (and of truncation) over `poses` poses.
// `exported`: the skin the export wrote (model vertices, see skinOfAsset), so
// the weights are not fitted a second time; null: computed here (exportSkin).
// `refit`: the corrective refit the export wrote (Asset::corrective_refit);
// null: computed here when the options ask for one.
Result<PruningError> measurePruningError(const BodyModel& model, const ExportOptions& options,
                                         int poses, const SparseSkin* exported = nullptr,
                                         const CorrectiveRefit* refit = nullptr);

// The report's held-out frames: `poses` uniform random poses (+-0.6 rad,
// seed 20261124) or, with `motion_like`, motion-like poses (seed 20261125).
std::vector<Rotations> heldOutFrames(const BodyModel& model, int poses, bool motion_like = false);

// Error of `skin` (N x M) with the correctives of `refit` (null or empty:
// the model's) against the unpruned model over `frames`.
Result<SkinError> measureSkinOn(const BodyModel& model, const ExportOptions& options,
                                const SparseSkin& skin, const CorrectiveRefit* refit,
                                const std::vector<Rotations>& frames);

// The skin an asset carries, per model vertex (N x M; asset vertices split at
// UV seams share their model vertex's weights): float weights widened.
SparseSkin skinOfAsset(const SkinnedMesh& mesh, int num_vertices);

// Held-out error of one N x K dense weight matrix over `poses` poses (seed 20261124).
Result<SkinError> measureSkinError(const BodyModel& model, const ExportOptions& options,
                                   const Eigen::MatrixXd& weights, int poses);

}  // namespace smpl
