#include "exporter/pruning_error.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "core/math/forward.h"
#include "core/math/forward_batch.h"
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

// The errors of several weight matrices on the same held-out poses, all
// poses at once through the batched forward pass (forwardBatchSkins: the
// corrective GEMM in float, once for the unpruned model and every weight
// set; < 1e-6 m from forward(), far below the millimetres measured here).
Result<std::vector<SkinError>> measureSkinErrors(const BodyModel& model,
                                                 const ExportOptions& options,
                                                 const std::vector<const Eigen::MatrixXd*>& weights,
                                                 int poses) {
  const ForwardInput shape = shapeInput(options);
  Result<ShapedBody> body = shapeBody(model, shape.betas, shape.expression);
  if (!body) return body.error();
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), poses, /*seed=*/20261124))
    frames.push_back(rotationsFromAxisAngle(pose));
  std::vector<const Eigen::MatrixXd*> skins = {nullptr};  // the model's own weights first
  for (const Eigen::MatrixXd* w : weights) {
    if (w->rows() != model.numVertices() || w->cols() != model.numJoints())
      return makeError("skin weights override has the wrong shape");
    skins.push_back(w);
  }
  BatchInput in;
  in.body = &*body;
  in.frames = &frames;
  in.block = 16;  // two blocks for the default 32 poses: both cores
  in.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<Eigen::MatrixXd> posed = forwardBatchSkins(model, in, skins);
  std::vector<SkinError> errs(weights.size());
  const Eigen::Index n = model.numVertices();
  for (size_t i = 0; i < weights.size(); ++i) {
    double sum = 0.0;
    for (Eigen::Index t = 0; t < posed[0].cols(); ++t)
      for (Eigen::Index v = 0; v < n; ++v) {
        const double d =
            (posed[0].col(t).segment<3>(3 * v) - posed[i + 1].col(t).segment<3>(3 * v)).norm();
        sum += d;
        errs[i].max_m = std::max(errs[i].max_m, d);
      }
    errs[i].mean_m = poses > 0 ? sum / (static_cast<double>(poses) * n) : 0.0;
  }
  return errs;
}

}  // namespace

Result<SkinError> measureSkinError(const BodyModel& model, const ExportOptions& options,
                                   const Eigen::MatrixXd& weights, int poses) {
  Result<std::vector<SkinError>> errs = measureSkinErrors(model, options, {&weights}, poses);
  if (!errs) return errs.error();
  return errs->front();
}

SparseSkin skinOfAsset(const SkinnedMesh& mesh, int num_vertices) {
  SparseSkin skin;
  skin.joints = Eigen::MatrixXi::Zero(num_vertices, mesh.joints.cols());
  skin.weights = Eigen::MatrixXd::Zero(num_vertices, mesh.weights.cols());
  for (Eigen::Index v = 0; v < mesh.joints.rows(); ++v) {
    const Eigen::Index source =
        mesh.source_vertex.empty() ? v : Eigen::Index(mesh.source_vertex[size_t(v)]);
    if (source < 0 || source >= num_vertices) continue;
    skin.joints.row(source) = mesh.joints.row(v);
    skin.weights.row(source) = mesh.weights.row(v).cast<double>();
  }
  return skin;
}

Result<PruningError> measurePruningError(const BodyModel& model, const ExportOptions& options,
                                         int poses, const SparseSkin* exported_skin) {
  ForwardInput shape = shapeInput(options);
  Result<ShapedBody> body = shapeBody(model, shape.betas, shape.expression);
  if (!body) return body.error();
  PruningError err;
  err.influences = influencesFor(model, options);
  err.poses = poses;
  const Eigen::MatrixXd truncated =
      denseWeights(pruneWeights(model.weights, err.influences), model.numJoints());
  if (options.skin_weights == SkinWeightMethod::Truncated) {
    Result<std::vector<SkinError>> t = measureSkinErrors(model, options, {&truncated}, poses);
    if (!t) return t.error();
    err.truncated = t->front();
    err.mean_m = err.truncated.mean_m, err.max_m = err.truncated.max_m;
    return err;
  }
  const Eigen::MatrixXd exported = denseWeights(
      exported_skin ? *exported_skin : exportSkin(model, *body, options), model.numJoints());
  Result<std::vector<SkinError>> e =
      measureSkinErrors(model, options, {&truncated, &exported}, poses);
  if (!e) return e.error();
  err.truncated = (*e)[0];
  err.mean_m = (*e)[1].mean_m, err.max_m = (*e)[1].max_m;
  return err;
}

}  // namespace smpl
