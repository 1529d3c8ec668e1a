#include "exporter/pruning_error.h"

#include <algorithm>

#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"
#include "exporter/export_skin.h"

namespace smpl {
namespace {

ForwardInput shapeInput(const ExportOptions& options) {
  ForwardInput input;
  input.betas =
      Eigen::Map<const Eigen::VectorXd>(options.betas.data(), Eigen::Index(options.betas.size()));
  input.expression = Eigen::Map<const Eigen::VectorXd>(options.expression.data(),
                                                       Eigen::Index(options.expression.size()));
  return input;
}

}  // namespace

Result<SkinError> measureSkinError(const BodyModel& model, const ExportOptions& options,
                                   const Eigen::MatrixXd& weights, int poses) {
  ForwardInput input = shapeInput(options);
  SkinError err;
  double sum = 0.0;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), poses, /*seed=*/20261124)) {
    input.rotations = rotationsFromAxisAngle(pose);
    input.weights = nullptr;
    Result<ForwardResult> full = forward(model, input);
    if (!full) return full.error();
    input.weights = &weights;
    Result<ForwardResult> cut = forward(model, input);
    if (!cut) return cut.error();
    Eigen::VectorXd dist = (full->vertices - cut->vertices).rowwise().norm();
    sum += dist.sum();
    err.max_m = std::max(err.max_m, dist.maxCoeff());
  }
  err.mean_m = poses > 0 ? sum / (static_cast<double>(poses) * model.numVertices()) : 0.0;
  return err;
}

Result<PruningError> measurePruningError(const BodyModel& model, const ExportOptions& options,
                                         int poses) {
  ForwardInput shape = shapeInput(options);
  Result<ShapedBody> body = shapeBody(model, shape.betas, shape.expression);
  if (!body) return body.error();
  PruningError err;
  err.influences = influencesFor(model, options);
  err.poses = poses;
  const Eigen::MatrixXd truncated =
      denseWeights(pruneWeights(model.weights, err.influences), model.numJoints());
  Result<SkinError> t = measureSkinError(model, options, truncated, poses);
  if (!t) return t.error();
  err.truncated = *t;
  if (options.skin_weights == SkinWeightMethod::Truncated) {
    err.mean_m = t->mean_m, err.max_m = t->max_m;
    return err;
  }
  const Eigen::MatrixXd exported =
      denseWeights(exportSkin(model, *body, options), model.numJoints());
  Result<SkinError> e = measureSkinError(model, options, exported, poses);
  if (!e) return e.error();
  err.mean_m = e->mean_m, err.max_m = e->max_m;
  return err;
}

}  // namespace smpl
