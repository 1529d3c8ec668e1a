// What one export builds, as plain data: ExportOptions and its choices
// (corrective encoding, skin weight method, origin). buildAsset (pipeline.h)
// and exportAsset (export_asset.h) take them; the request fills them
// (request/request_options.h exportOptionsOf). Apart from the pipeline so that
// what only needs the options (the request, the skin) does not include it.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace smpl {

// How corrective weights are encoded (docs/file-contract.md "Pose correctives as morph targets").
//   Signed: weight = f[n] (diagonal features in [-2, 0], off-diagonal in [-1, 1]).
//   Unit:   weight = 0.5 f[n] + o, o = 1 (diagonal) or 0.5 (off-diagonal), so
//           weights stay in [0, 1] for engines and importers that clamp; the
//           deltas are 2 P_n and the stored base mesh is v_shaped - sum 2 o P_n,
//           so the rest pose (weights = o, written as the default weights)
//           is exactly v_shaped. The mapping is in the metadata.
//   Split:  exact with every weight at zero and every weight in [0, 1]:
//           diagonal feature n (f in [-2, 0]) -> one target pose_<joint>_<rc>,
//           delta -2 P_n, weight max(0, -f/2); off-diagonal (f in [-1, 1]) ->
//           pose_<joint>_<rc>_pos (delta P_n, weight max(0, f)) and
//           pose_<joint>_<rc>_neg (delta -P_n, weight max(0, -f)). Base mesh
//           v_shaped, rest weights 0; metadata entries carry "rectified".
//   Auto:   Split when the export bakes an animation (importers such as
//           Blender's clamp animated weights to [0, 1], and some ignore the
//           file's default weights, which Unit relies on), else Signed.
enum class CorrectiveEncoding { Auto, Signed, Unit, Split };

// "signed", "unit" or "split" (Auto: "signed", as buildAsset treats it).
const char* correctiveEncodingName(CorrectiveEncoding encoding);

// How the M skin influences per vertex are chosen (exporter/export_skin.h):
//   Truncated: the M largest model weights, renormalised to sum 1.
//   Optimized: the same M joints, weights fitted (non-negative, sum 1) to the
//              unpruned model over training poses (core/math/skin_weight_fit.h).
enum class SkinWeightMethod { Truncated, Optimized };

// Where the asset's origin is (--origin, exporter/placement.h):
//   Model  the model's own frame (the pelvis J_0 where the model puts it)
//   Floor  one constant shift in y so that the body's lowest point is at
//          y = 0: the rest mesh without a motion, else the lowest posed
//          vertex over every frame of every clip (placement.h lowestPoint)
enum class Origin { Model, Floor };

// Which names the skeleton's bones carry (--skeleton-names, exporter/skeleton_names.h):
//   Smpl    the model's joint names (pelvis, left_hip, ...), as always
//   Mixamo  Adobe Mixamo's rig names (mixamorig:Hips, mixamorig:LeftUpLeg, ...)
//   Ue5     the Unreal Engine 5 Mannequin's (pelvis, thigh_l, ...)
// Joints the target rig has no bone for keep the model's name. Only bone
// names change: morph target names and every number stay the same.
enum class SkeletonNames { Smpl, Mixamo, Ue5 };

// The skeleton's rest pose (--rest-pose, exporter/rest_pose.h): T the
// model's own (arms horizontal), A the arms 45 degrees down (skeleton-only
// formats: BVH).
enum class RestPose { T, A };

// ExportOptions::max_influences value for "every joint" (--max-influences all).
constexpr int kAllInfluences = 0;

struct ExportOptions {
  std::vector<double> betas;       // zero-padded to the model's count; more is an error
  std::vector<double> expression;  // SMPL-X only
  int max_influences = 4;          // 1..K (clamped), or kAllInfluences
  SkinWeightMethod skin_weights = SkinWeightMethod::Optimized;  // --skin-weights
  bool correctives = true;                                      // one morph target per pose feature
  // --corrective-refit: the corrective deltas of vertices whose influences
  // were cut are refitted so that the exported skin + correctives reproduce
  // the unpruned model (core/math/corrective_refit.h); false: posedirs as is.
  // Applies to per-feature targets only (refitsCorrectives).
  bool corrective_refit = true;
  CorrectiveEncoding encoding =
      CorrectiveEncoding::Auto;  // resolved by the caller; Auto acts as Signed here
  int corrective_basis = 0;      // > 0: K principal components of posedirs replace the P
                                 // per-feature targets; weights = C f (C in the metadata)
  int shape_keys = 0;            // also export the first N shape directions
  int expression_keys = 0;       // also export the first N expression directions
  std::string uv_obj;            // --uv: "" = the model file's vt/ft if any, "none" = no UVs,
                                 // an OBJ in the model's vertex order, or <stem>_uv.npy/_ft.npy
  std::string name = "body";
  bool quantize_morphs = false;  // --quantize-morphs: exportAsset folds each corrective's peak
                                 // into its weights and marks it quantized (morph_scales.h)
  // false: a skeleton-only asset (the writer has no mesh, writers/writer.h):
  // no UVs, no skin (nothing fitted), no morph targets.
  bool mesh = true;
  // --origin (exportAsset applies it after baking); none: Model, or Floor
  // with root_bone (a root joint stands on the floor)
  std::optional<Origin> origin;
  bool root_bone = false;  // --root-bone: a `root` joint (placement.h); implies Floor
  // --skeleton-names: exportAsset renames the bones last (skeleton_names.h)
  SkeletonNames skeleton_names = SkeletonNames::Smpl;
  // --rest-pose: exportAsset re-expresses the rest and the keys after the
  // placement, before the renaming (rest_pose.h)
  RestPose rest_pose = RestPose::T;
  // Workers of the skin-weight fit and the corrective refit (--threads; 0:
  // all cores). Their split never changes a sum: the same bytes for any count.
  int threads = 0;
};

// Whether an export with `o` refits its correctives: corrective_refit, with
// per-feature corrective targets (a --corrective-basis export keeps the
// model's posedirs: its K components are a lossy fit of them, documented and
// tested as such; the refit would change what they approximate).
inline bool refitsCorrectives(const ExportOptions& o) {
  return o.mesh && o.correctives && o.corrective_refit && o.corrective_basis == 0;
}

}  // namespace smpl
