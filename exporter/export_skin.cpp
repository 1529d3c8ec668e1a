#include "exporter/export_skin.h"

#include <algorithm>

#include "core/math/skin_weight_fit.h"
#include "core/parallel.h"

namespace smpl {

int influencesFor(const BodyModel& model, const ExportOptions& options) {
  if (options.max_influences == kAllInfluences) return model.numJoints();
  return std::max(1, std::min(options.max_influences, model.numJoints()));
}

namespace {

// Drops trailing slots that no vertex uses (rows are sorted by descending weight).
SparseSkin trimUnusedSlots(SparseSkin skin) {
  Eigen::Index used = 1;
  for (Eigen::Index s = 0; s < skin.weights.cols(); ++s)
    if ((skin.weights.col(s).array() > 0).any()) used = s + 1;
  skin.joints.conservativeResize(Eigen::NoChange, used);
  skin.weights.conservativeResize(Eigen::NoChange, used);
  return skin;
}

}  // namespace

SparseSkin exportSkin(const BodyModel& model, const ShapedBody& body,
                      const ExportOptions& options) {
  const int m = influencesFor(model, options);
  SparseSkin skin;
  if (options.skin_weights == SkinWeightMethod::Truncated) {
    skin = pruneWeights(model.weights, m);
  } else {
    SkinFitOptions fit;
    fit.max_influences = m;
    fit.threads = options.threads > 0 ? options.threads : int(hardwareThreads());
    skin = fitSkinWeights(model, body, fit);
  }
  // "all": as many influences as the model's vertices use, not K slots each.
  return options.max_influences == kAllInfluences ? trimUnusedSlots(std::move(skin)) : skin;
}

const char* skinWeightMethodName(SkinWeightMethod method) {
  return method == SkinWeightMethod::Truncated ? "truncated" : "optimized";
}

}  // namespace smpl
