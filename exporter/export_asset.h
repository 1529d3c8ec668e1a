// exportAsset(): the whole library side of an export, model + options +
// motions -> the finished Asset every writer serialises as it is. After
// buildAsset (pipeline.h) it bakes each motion (animation.h), applies the
// quantisation fold when asked (morph_scales.h: deltas / s_n, weights and the
// metadata mapping * s_n) and runs validateAsset (validate_asset.h), so the
// writers (writers/) only translate and the sidecar written beside a file
// carries the same numbers as the file.
//
//   std::vector<MotionInput> motions = {{&walk, "walk.npz", AnimationOptions(), nullptr}};
//   Result<Asset> asset = exportAsset(model, options, motions);
#pragma once

#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/motions/motion.h"
#include "core/result.h"
#include "exporter/animation.h"
#include "exporter/asset.h"
#include "exporter/dmpl_targets.h"
#include "exporter/pipeline.h"

namespace smpl {

// Wall time of exportAsset's two parts, in seconds: `fit` is buildAsset (the
// shaped mesh, the skin fit or its reuse from a SkinCache, the corrective
// refit), `bake` everything after it (DMPL and expression targets, the motions'
// clips, placement, folding, validation). For benchmarks and batch totals.
struct ExportTimes {
  double fit = 0.0;
  double bake = 0.0;
};

// One motion to bake into the asset: the motion (not owned, outlives the
// call), the path or name that errors name, how to bake it (fps, frame range,
// up axis) and an optional progress callback (fraction in [0, 1]).
// `release`: null, or the same motion when the caller needs none of its
// frames after the call: the bake then frees them as it passes them
// (bakeAnimation), unless the export bakes it a second time (a skeleton-only
// export placed on the floor measures the full body's clip).
struct MotionInput {
  const Motion* motion = nullptr;
  std::string context;
  AnimationOptions animation;
  Progress progress;
  Motion* release = nullptr;
};

// CorrectiveEncoding::Auto resolved for an export with `motions` baked
// animations: Signed without one; with one, weights must survive importers
// that clamp them to [0, 1] (Blender) and importers that ignore the file's
// default weights (three.js FBXLoader): Split, or Unit with a corrective
// basis (a basis has no split form). Other encodings unchanged.
CorrectiveEncoding resolveEncoding(CorrectiveEncoding encoding, size_t motions, bool basis = false);

// buildAsset(model, options with the encoding resolved), one AnimationClip per
// motion in order (asset.animations[i] from motions[i]), then, when
// options.quantize_morphs, foldMorphScales; then every name escaped into
// valid UTF-8 (asset_names.h: a motion file named "walk\xff.npz" gives the
// clip "walk\\xff"); last validateAsset. Errors: those
// of buildAsset, bakeAnimation (naming motions[i].context) and validateAsset;
// one line each, no partial asset.
// `dmpl` (optional): DMPL soft-tissue targets added after buildAsset, before
// baking (dmpl_targets.h).
// `skins` (optional): the fitted skin shared with exports of the same subject
// (buildAsset, exporter/skin_cache.h).
// `times` (optional): where the call's wall time went, in seconds (ExportTimes).
Result<Asset> exportAsset(const BodyModel& model, const ExportOptions& options,
                          const std::vector<MotionInput>& motions, const DmplInput* dmpl = nullptr,
                          SkinCache* skins = nullptr, ExportTimes* times = nullptr);

}  // namespace smpl
