// The format-neutral asset: everything a writer serialises, nothing it must
// compute. The pipeline (pipeline.h) builds it from a model and options; the
// writers (writers/) only translate it into bytes. Plain data, model axes
// (metres, +Y up, right-handed), float32 where the files store float32.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "core/math/corrective_refit.h"
#include "core/memory_budget.h"

namespace smpl {

struct Skeleton {
  std::vector<std::string> names;  // K joint names (bone/node names)
  std::vector<int> parents;        // K; -1 for the root
  Eigen::MatrixXd rest_local;      // K x 3 local translation J_k - J_p(k) (root: J_0)
  Eigen::MatrixXd rest_world;      // K x 3 rest joint positions J_k
  // Rest local rotations are identity by contract (docs/file-contract.md); inverse bind
  // matrix of joint k is translation(-J_k).
};

// V x 3 position deltas, row-major: a vertex's x, y, z contiguous, as
// glTF's float POSITION targets store them (the writer uses them without a copy).
using MorphDeltas = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct MorphTarget {
  std::string name;          // pose_<joint>_<r><c>, shape_<i>, expr_<i>
  MorphDeltas deltas;        // V x 3 position deltas (V = asset vertex count)
  float rest_weight = 0.0f;  // weight at the rest pose (non-zero for the unit encoding)
  bool quantized = false;    // stored as normalised int16 (KHR_mesh_quantization): deltas
                             // already divided by their peak s_n, |delta| <= 1 (morph_scales.h)
  double peak = 1.0;         // s_n the deltas were divided by (1 if not quantized):
                             // deltas * peak are metres
};

struct SkinnedMesh {
  Eigen::MatrixXf positions;       // V x 3 rest mesh (v_shaped), may be split at UV seams
  Eigen::MatrixXf normals;         // V x 3 unit normals of the rest mesh
  Eigen::MatrixXf uvs;             // V x 2 (OBJ convention, v up), or 0 rows when absent
  Eigen::MatrixXi triangles;       // F x 3, counter-clockwise seen from outside
  Eigen::MatrixXi joints;          // V x M joint indices
  Eigen::MatrixXf weights;         // V x M, rows sum to 1
  std::vector<int> source_vertex;  // V: model vertex each asset vertex came from
  std::vector<MorphTarget> morph_targets;
};

// One entry per corrective morph target: weight = scale * f[feature] + offset.
struct CorrectiveLayout {
  int feature = 0;     // index into f (docs/file-contract.md order)
  std::string target;  // morph target name
  double scale = 1.0;
  double offset = 0.0;
  bool rectified = false;  // split encoding: weight = max(0, scale * f[feature] + offset)
};

// --corrective-basis K (exporter/corrective_basis.h): K morph targets replace
// the per-feature correctives; weight_k = scale_k * (projection f)_k + offset_k.
struct CorrectiveBasis {
  std::vector<std::string> targets;  // K morph target names pose_basis_<k>
  Eigen::MatrixXd projection;        // K x P (C); 0 rows = no basis (per-feature layout)
  std::vector<double> scale;         // K
  std::vector<double> offset;        // K
};

// DMPL soft-tissue target (exporter/dmpl_targets.h): weight = scale * c[direction] + offset,
// c = the motion's `dmpls` row of the frame.
struct DmplLayout {
  int direction = 0;   // column of the basis / of `dmpls`
  std::string target;  // morph target name dmpl_<i>
  double scale = 1.0;
  double offset = 0.0;
};

struct DmplInfo {
  std::string basis;            // basis file name ("" = no DMPL targets)
  bool animate_joints = false;  // --dmpl-joints regressed: per-frame joint translations
  std::vector<DmplLayout> targets;
  Eigen::MatrixXd
      joint_directions;  // 3K x D: J_regressor * direction d, row 3k + c (not serialised)
};

// Animated SMPL-X expressions (exporter/expression_targets.h): the expr_<i>
// target of expression coefficient `index` is driven by
// weight = scale * (psi_index(t) - psi_index_rest) + offset, in [0, 1] over the
// baked motions (importers that clamp play it exactly); psi_rest is the
// static --expression (AssetMetadata::expression).
struct ExpressionLayout {
  int index = 0;
  std::string target;  // expr_<index>
  double scale = 1.0;
  double offset = 0.0;
};

struct ExpressionInfo {
  std::vector<ExpressionLayout> targets;  // empty: expr_<i> weights are the coefficients (static)
  Eigen::MatrixXd joint_directions;       // 3K x E: J_regressor * exprdirs column i, row 3k + c
                                          // (the joints' motion, for the cost; not serialised)
};

// Where a clip came from, recorded in the metadata: the motion layout that
// read it, the person/track of a multi-person file, the source frames baked
// ([first_frame, end_frame) in the file's own numbering) and how its world
// was turned to Y-up.
struct ClipSource {
  std::string layout;  // motion reader table row ("amass", "fit", ...)
  std::string track;   // "" for a single-person file
  int64_t first_frame = 0, end_frame = 0;
  std::string world = "y";  // "y", "z" (turned -90 degrees about x) or "-y" (a half turn about x)
};

// One joint's T local rotations as unit quaternions in float, (x, y, z, w)
// contiguous: the bytes of glTF's rotation output (the writer uses them
// without a copy). The bake normalises in double and rounds once.
using RotationTrack = std::vector<Eigen::Quaternionf>;

// T x (#morph targets) weights, row-major: frame t's weights are contiguous,
// as glTF's "weights" output stores them (the writer uses them without a copy).
using MorphWeightTrack = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct AnimationClip {
  std::string name;
  double fps = 30.0;
  std::vector<double> times;                      // T seconds
  std::vector<RotationTrack> rotations;           // [joint][frame] local rotations
  std::vector<Eigen::Vector3d> root_translation;  // T root node translations (model axes)
  MorphWeightTrack morph_weights;                 // T x (#morph targets), in target order
  // [joint][frame] local translations (--dmpl-joints regressed: every joint;
  // --root-bone: the pelvis); empty = rest_local for every joint, and an empty
  // track of one joint = its rest_local (no track written). Joint 0's track,
  // when given, equals root_translation.
  std::vector<std::vector<Eigen::Vector3d>> joint_translations;
  double dmpl_joint_error = 0.0;        // max vertex error (m) that betas-only joints cost (DMPL)
  double expression_joint_error = 0.0;  // the same for an animated expression (m)
  ClipSource source;
  std::vector<std::string> notes;  // for the user, one line each (what was dropped or assumed)
  // Motion joints the model lacks, dropped by the mapping this clip was baked
  // with (MotionMapping::dropped, animation.h), for the run's notes; not written.
  std::vector<std::string> dropped_joints;
  MemoryCharge charge;  // the arrays above, against the memory budget
};

struct AssetMetadata {
  std::string model_kind;  // "smpl", "smplh", "smplx", "mano"
  std::string model_name;  // source file name or "builtin"
  std::string exporter_version;
  std::vector<double> betas;
  std::vector<double> expression;
  std::vector<CorrectiveLayout> correctives;  // empty when corrective_basis is used
  int max_influences = 4;
  std::string units = "meters";
  std::string up_axis = "+Y";
  CorrectiveBasis corrective_basis;  // last: keeps aggregate initialisers of the fields above valid
  // Added after corrective_basis for the same reason (aggregate initialisers stay valid).
  std::string skin_weights = "truncated";      // "truncated" or "optimized" (export_skin.h)
  std::string corrective_encoding = "signed";  // "signed", "unit" or "split" (export_options.h)
  DmplInfo dmpl{};  // DMPL soft-tissue targets (empty without --dmpl); last, as above
  ExpressionInfo expression_targets{};  // animated expressions (empty: static); last, as above
  // --skeleton-names (skeleton_names.h): "smpl" (the bones carry the model's
  // joint names), "mixamo" or "ue5"; then model_joint_names holds the model's
  // name of every Skeleton joint (Skeleton::names holds the bones' names).
  // Last, as above.
  std::string skeleton_names = "smpl";
  std::vector<std::string> model_joint_names{};
  // --rest-pose (rest_pose.h): "t" (the model's T rest, identity rest
  // rotations) or "a" (the skeleton's offsets and keys at an A-pose rest).
  // Last, as above.
  std::string rest_pose = "t";
};

// Where the asset stands (exporter/placement.h): --origin and --root-bone.
// Defaults: the model's own origin (the pelvis at J_0), no root bone.
struct Placement {
  std::string origin = "model";  // "model" or "floor"
  double floor_offset = 0.0;     // metres added to every y (floor: -(lowest y); model: 0)
  // --root-bone: Skeleton joint 0 is `root` (not a model joint, parent -1,
  // identity rotation, on the floor below the pelvis); the model's joints
  // follow in model order at 1..K (parents + 1), and skin joint indices are
  // shifted by one. Metadata joint_names/parents list the model's joints only.
  bool root_bone = false;
};

struct Asset {
  std::string name;  // mesh / scene name
  Skeleton skeleton;
  SkinnedMesh mesh;
  std::vector<AnimationClip> animations;
  AssetMetadata metadata;
  // A skeleton-only asset (for a writer without a mesh, writers/writer.h
  // needs_mesh = false): `mesh` is empty and validateAssetStructure does not
  // require one. Last: keeps aggregate initialisers of the fields above valid.
  bool skeleton_only = false;
  // The refitted corrective rows the morph targets carry (empty: posedirs
  // as is), kept so the error report measures what was written; writers
  // ignore it (the targets already hold the deltas). Never null; shared, not
  // copied, with the batch's other exports of the subject (exporter/skin_cache.h).
  std::shared_ptr<const CorrectiveRefit> corrective_refit = std::make_shared<CorrectiveRefit>();
  Placement placement;  // last, as above
};

}  // namespace smpl
