#include "exporter/pruning_error.h"

#include <algorithm>
#include <thread>
#include <vector>

#include "core/math/forward.h"
#include "core/math/forward_batch.h"
#include "core/math/motion_poses.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"
#include "core/parallel.h"
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

// One skin to measure: dense N x K weights, and for the refit its sparse
// form and the refitted correctives (null: the model's).
struct SkinCase {
  Eigen::MatrixXd weights;
  const SparseSkin* skin = nullptr;
  const CorrectiveRefit* refit = nullptr;
};

// The errors of several skins on the same frames, all frames at once through
// the batched forward pass (forwardBatchSkins: the corrective GEMM in float,
// once for the unpruned model and every weight set; < 1e-6 m from forward(),
// far below the millimetres measured here); a refit's change is added in
// double (addRefitCorrection).
Result<std::vector<SkinError>> measureSkinErrors(const BodyModel& model,
                                                 const ExportOptions& options,
                                                 const std::vector<SkinCase>& cases,
                                                 const std::vector<Rotations>& frames) {
  const ForwardInput shape = shapeInput(options);
  Result<ShapedBody> body = shapeBody(model, shape.betas, shape.expression);
  if (!body) return body.error();
  // The model's own weights first; a case with the weights of an earlier one
  // (the refit's, which shares its skin) reuses that forward pass.
  std::vector<const Eigen::MatrixXd*> skins = {nullptr};
  std::vector<size_t> pass(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    const Eigen::MatrixXd& w = cases[i].weights;
    if (w.rows() != model.numVertices() || w.cols() != model.numJoints())
      return makeError("skin weights override has the wrong shape");
    size_t j = 0;
    while (j < i && cases[j].weights != w) ++j;
    if (j < i) {
      pass[i] = pass[j];
    } else {
      pass[i] = skins.size();
      skins.push_back(&w);
    }
  }
  BatchInput in;
  in.body = &*body;
  in.frames = &frames;
  in.block = 16;  // two blocks for the default 32 poses: both cores
  in.threads = static_cast<int>(hardwareThreads());
  const std::vector<Eigen::MatrixXd> posed = forwardBatchSkins(model, in, skins);
  std::vector<SkinError> errs(cases.size());
  const Eigen::Index n = model.numVertices();
  const double count = static_cast<double>(frames.size()) * double(n);
  for (size_t i = 0; i < cases.size(); ++i) {
    Eigen::MatrixXd corrected;
    const bool refit = cases[i].refit && cases[i].skin;
    if (refit) {
      corrected = posed[pass[i]];
      addRefitCorrection(model, *body, *cases[i].skin, *cases[i].refit, frames, &corrected);
    }
    const Eigen::MatrixXd& mine = refit ? corrected : posed[pass[i]];
    double sum = 0.0;
    for (Eigen::Index t = 0; t < posed[0].cols(); ++t)
      for (Eigen::Index v = 0; v < n; ++v) {
        const double d = (posed[0].col(t).segment<3>(3 * v) - mine.col(t).segment<3>(3 * v)).norm();
        sum += d;
        errs[i].max_m = std::max(errs[i].max_m, d);
      }
    errs[i].mean_m = count > 0 ? sum / count : 0.0;
  }
  return errs;
}

}  // namespace

std::vector<Rotations> heldOutFrames(const BodyModel& model, int poses, bool motion_like) {
  const std::vector<Eigen::VectorXd> p =
      motion_like ? sampleMotionPoses(model.joint_names, poses, /*seed=*/20261125)
                  : samplePoses(model.numJoints(), poses, /*seed=*/20261124);
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : p) frames.push_back(rotationsFromAxisAngle(pose));
  return frames;
}

Result<SkinError> measureSkinError(const BodyModel& model, const ExportOptions& options,
                                   const Eigen::MatrixXd& weights, int poses) {
  Result<std::vector<SkinError>> errs =
      measureSkinErrors(model, options, {SkinCase{weights}}, heldOutFrames(model, poses));
  if (!errs) return errs.error();
  return errs->front();
}

Result<SkinError> measureSkinOn(const BodyModel& model, const ExportOptions& options,
                                const SparseSkin& skin, const CorrectiveRefit* refit,
                                const std::vector<Rotations>& frames) {
  Result<std::vector<SkinError>> errs = measureSkinErrors(
      model, options, {SkinCase{denseWeights(skin, model.numJoints()), &skin, refit}}, frames);
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
                                         int poses, const SparseSkin* exported_skin,
                                         const CorrectiveRefit* exported_refit) {
  ForwardInput shape = shapeInput(options);
  Result<ShapedBody> body = shapeBody(model, shape.betas, shape.expression);
  if (!body) return body.error();
  PruningError err;
  err.influences = influencesFor(model, options);
  err.poses = poses;
  const SparseSkin truncated = pruneWeights(model.weights, err.influences);
  const SparseSkin skin = exported_skin ? *exported_skin
                          : options.skin_weights == SkinWeightMethod::Truncated
                              ? truncated
                              : exportSkin(model, *body, options);
  CorrectiveRefit computed;
  const CorrectiveRefit* refit = exported_refit;
  if (!refit && refitsCorrectives(options)) {
    computed = refitCorrectives(model, *body, skin, CorrectiveRefitOptions());
    refit = &computed;
  }
  err.refit = refit && !refit->empty();
  const int k = model.numJoints();
  std::vector<SkinCase> cases = {SkinCase{denseWeights(truncated, k)},
                                 SkinCase{denseWeights(skin, k)}};
  if (err.refit) cases.push_back(SkinCase{cases[1].weights, &skin, refit});
  Result<std::vector<SkinError>> e =
      measureSkinErrors(model, options, cases, heldOutFrames(model, poses));
  if (!e) return e.error();
  err.truncated = (*e)[0];
  err.without_refit = (*e)[1];
  const SkinError& exported = e->back();
  err.mean_m = exported.mean_m, err.max_m = exported.max_m;
  return err;
}

}  // namespace smpl
