#include "exporter/pruning_error.h"

#include <algorithm>

#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"

namespace smpl {

Result<PruningError> measurePruningError(const BodyModel& model, const ExportOptions& options, int poses) {
  const int m = std::min(options.max_influences, model.numJoints());
  const Eigen::MatrixXd pruned = denseWeights(pruneWeights(model.weights, m), model.numJoints());
  ForwardInput input;
  input.betas = Eigen::Map<const Eigen::VectorXd>(options.betas.data(), options.betas.size());
  input.expression = Eigen::Map<const Eigen::VectorXd>(options.expression.data(), options.expression.size());
  PruningError err;
  double sum = 0.0;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), poses, /*seed=*/20261124)) {
    input.rotations = rotationsFromAxisAngle(pose);
    input.weights = nullptr;
    Result<ForwardResult> full = forward(model, input);
    if (!full) return full.error();
    input.weights = &pruned;
    Result<ForwardResult> cut = forward(model, input);
    if (!cut) return cut.error();
    Eigen::VectorXd dist = (full->vertices - cut->vertices).rowwise().norm();
    sum += dist.sum();
    err.max_m = std::max(err.max_m, dist.maxCoeff());
  }
  err.poses = poses;
  err.mean_m = poses > 0 ? sum / (static_cast<double>(poses) * model.numVertices()) : 0.0;
  return err;
}

}  // namespace smpl
