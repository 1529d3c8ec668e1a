#include "exporter/export_asset.h"

#include <cmath>

#include "core/math/eigen_blocking.h"
#include "core/stopwatch.h"
#include "exporter/asset_names.h"
#include "exporter/expression_targets.h"
#include "exporter/morph_scales.h"
#include "exporter/placement.h"
#include "exporter/rest_pose.h"
#include "exporter/skeleton_names.h"
#include "exporter/validate_asset.h"

namespace smpl {

CorrectiveEncoding resolveEncoding(CorrectiveEncoding encoding, size_t motions, bool basis) {
  if (encoding != CorrectiveEncoding::Auto) return encoding;
  if (motions == 0) return CorrectiveEncoding::Signed;
  return basis ? CorrectiveEncoding::Unit : CorrectiveEncoding::Split;
}

namespace {

// The lowest point of a skeleton-only export (no mesh of its own): the same
// export with the model's full skin (every influence, the model's weights)
// and its correctives, baked the same way (placement.h lowestPoint).
Result<double> lowestOfModel(const BodyModel& model, const ExportOptions& options,
                             const std::vector<MotionInput>& motions, const DmplInput* dmpl) {
  ExportOptions full = options;
  full.mesh = true;
  full.max_influences = kAllInfluences;
  full.skin_weights = SkinWeightMethod::Truncated;
  full.origin = Origin::Model;
  full.root_bone = false;
  full.quantize_morphs = false;
  // The T rest's mesh: an A rest moves no posed vertex, and only a skeleton
  // takes one (rest_pose.h); the arms it lowers stay above the feet.
  full.rest_pose = RestPose::T;
  Result<Asset> asset = exportAsset(model, full, motions, dmpl);
  if (!asset) return asset.error();
  return lowestPoint(*asset);
}

// --origin floor / --root-bone on the baked asset (placement.h).
Status placeAsset(const BodyModel& model, const ExportOptions& options,
                  const std::vector<MotionInput>& motions, const DmplInput* dmpl, Asset* asset) {
  if (options.origin == Origin::Floor || options.root_bone) {
    Result<double> lowest = asset->skeleton_only ? lowestOfModel(model, options, motions, dmpl)
                                                 : Result<double>(lowestPoint(*asset));
    if (!lowest) return lowest.error();
    if (!std::isfinite(*lowest))
      return makeError("--origin floor: the body's lowest point is not finite");
    shiftAssetUp(asset, -*lowest);
  }
  if (options.root_bone) addRootBone(asset);
  return Status();
}

}  // namespace

Result<Asset> exportAsset(const BodyModel& model, const ExportOptions& options,
                          const std::vector<MotionInput>& motions, const DmplInput* dmpl,
                          SkinCache* skins, ExportTimes* times) {
  useFixedEigenBlocking();
  const SteadyTime start = steadyNow();
  ExportOptions resolved = options;
  resolved.encoding =
      resolveEncoding(options.encoding, motions.size(), options.corrective_basis > 0);
  Result<Asset> asset = buildAsset(model, resolved, skins);
  if (!asset) return asset;
  const SteadyTime built = steadyNow();
  if (times) times->fit = secondsSince(start);
  if (dmpl && dmpl->basis && !asset->skeleton_only)  // DMPL targets need a mesh
    addDmplTargets(model, *dmpl->basis, dmpl->layout, dmpl->animate_joints, &*asset);
  std::vector<const Eigen::MatrixXd*> expressions;  // animated SMPL-X expressions
  for (const MotionInput& m : motions)
    if (m.motion && m.motion->expression.rows() > 0) expressions.push_back(&m.motion->expression);
  if (!expressions.empty() && resolved.expression_keys > 0)
    encodeExpressionTargets(
        model, expressionLayout(resolved.expression_keys, asset->metadata.expression, expressions),
        &*asset);
  // lowestOfModel (placeAsset) bakes the motions again.
  const bool baked_again =
      asset->skeleton_only && (options.origin == Origin::Floor || options.root_bone);
  for (const MotionInput& m : motions) {
    if (!m.motion) return makeError(m.context + ": no motion given");
    Result<AnimationClip> clip = bakeAnimation(model, *asset, *m.motion, m.animation, m.context,
                                               m.progress, baked_again ? nullptr : m.release);
    if (!clip) return clip.error();
    asset->animations.push_back(std::move(*clip));
  }
  if (Status st = placeAsset(model, options, motions, dmpl, &*asset); !st) return st.error();
  // After the placement: the A rest keeps every posed joint where it put them.
  if (options.rest_pose == RestPose::A)
    if (Status st = applyARestPose(&*asset); !st) return st.error();
  // Quantized targets carry their scale s_n in the weight mapping: folded
  // here so every writer and the sidecar see the same numbers.
  if (options.quantize_morphs) foldMorphScales(&*asset);
  // Names from file names or the command line may hold bytes that are not
  // UTF-8; every output format needs UTF-8 text (asset_names.h).
  escapeAssetNames(&*asset);
  // Last: the bake, the placement and the morph target names above use the
  // model's joint names (and they are escaped; the table's are ASCII).
  renameSkeleton(options.skeleton_names, &*asset);
  if (Status st = validateAsset(*asset); !st) return st.error();
  if (times) times->bake = secondsSince(built);
  return asset;
}

}  // namespace smpl
