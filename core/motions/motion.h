// Pose sequences, recognised by their keys (not by the extension), through
// the motion reader table (core/motions/motion_layout.h; one row per layout:
// AMASS and plain poses (motion_amass.h), Meshcapade SMPLCodec `.smpl`
// (motion_smplcodec.h), SMPL-X / SMPL fits (motion_fit.h), AIST++
// (motion_aist.h); docs/motions.md lists them with the tools that write them).
// The container is chosen by content (core/motions/motion_read.h). Every frame
// is validated (finite numbers, consistent lengths, rotations) before
// anything is exported.
// A file with no pose keys at all (AMASS `shape.npz`, `*_stagei.npz`, a
// shape-only .smpl) is "no pose data": loadMotion fails on it and
// hasPoseData() says so without failing (batch mode skips such files); a
// file with pose-like keys of a layout no row reads fails with the keys it
// has and a pointer to docs/motions.md.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/array.h"
#include "core/body_model.h"
#include "core/data_node.h"
#include "core/math/forward.h"
#include "core/memory_budget.h"
#include "core/motions/scene_camera.h"
#include "core/result.h"

namespace smpl {

// Hand poses of a fit that need the model to become rotations: PCA
// coefficients of the model's hands_components, and/or axis-angle poses to
// which the model's hands_mean is added (motion_fit.h). Empty otherwise.
struct PendingHands {
  std::vector<Eigen::VectorXd> left, right;  // T entries of C values each (C = 45: full pose)
  // Non-empty: a model without hands_mean keeps these hands at rest with this
  // note instead of failing (GVHMR: its hands are only the model's mean hand).
  std::string rest_without_mean;
  bool active() const { return !left.empty() || !right.empty(); }
};

// The world a motion's root rotations and translations are expressed in;
// the export is always Y-up (exporter/animation.h turns the whole body).
//   Y            a Y-up world (most fitters and generators)
//   Z            a Z-up capture world (AMASS)
//   CameraYDown  a camera frame as OpenCV has it: x right, y down, z forward
//                (the output of video methods in camera coordinates)
enum class MotionWorld { Y, Z, CameraYDown };

struct Motion {
  std::string name;                          // file stem
  ModelKind layout = ModelKind::Smpl;        // joint layout of `rotations`
  double fps = 30.0;                         // source frames per second
  bool fps_assumed = false;                  // no rate was stored: fps is a default (see notes)
  std::vector<Rotations> frames;             // T x J local rotations, source layout order
  std::vector<Eigen::Vector3d> translation;  // T root translations in metres (zeros if absent)
  std::vector<double> betas;                 // empty if the file has none
  std::string gender;                        // "" if absent
  Eigen::MatrixXd dmpls;  // T x D DMPL soft-tissue coefficients (AMASS `dmpls`); 0 x 0 if absent
  std::string dmpls_problem;  // "<path>: 'dmpls' ..." when present but unusable (shape, NaN); the
                              // error of an export that needs them (core/models/dmpl.h)
  MotionWorld world = MotionWorld::Y;  // what the layout says of the file's world (--up overrides)
  std::string world_why;  // for a camera frame: the note saying so ("WHAM 'pose' is in the camera
                          // frame"), printed when no --up is given
  Eigen::MatrixXd expression;  // T x E SMPL-X expression coefficients per frame; 0 x 0 if absent
  std::string track;           // the person or track id in a multi-person file; "" if it has one
  int64_t first_frame = 0;     // source frame number of frames[0] (a track that starts later)
  int64_t held_frames = 0;     // frames without a detection, holding the previous one (tracks)
  // Per clip frame: true where the source had no detection and the frame holds
  // the previous one (assembleTrack); empty when every frame is a detection.
  std::vector<bool> held;
  // Per-frame frame change applied to the whole posed body about the world
  // origin, before the world turn: v -> world_rotation[f] v + world_translation[f]
  // (EasyMocap's Rh/Th, TRAM's camera-to-world). Empty: identity. The bake
  // knows J_0: the root becomes A R_0 and the root node A (J_0 + t) + b.
  std::vector<Eigen::Matrix3d> world_rotation;
  std::vector<Eigen::Vector3d> world_translation;
  // Model joint names whose posed mid-point the translation places (BEV's
  // root-aligned vertices: {left_hip, right_hip}): with p the mean of their
  // rest positions J (the export's betas) and R_0 the root rotation, the body
  // is LBS(pose) + t - (J_0 + R_0 (p - J_0)), so the root node sits at
  // t - R_0 (p - J_0) (the bake knows J: exporter/animation.cpp). Empty: t is
  // the usual SMPL transl.
  std::vector<std::string> translation_anchor;
  std::string hand;  // MANO motions: "right" or "left" (HaMeR's is_right); "" otherwise
  // The body model the file names, when it names one (AMASS `surface_model_type`):
  // --model DIR picks that kind rather than the one of the joint layout.
  std::optional<ModelKind> model_kind;
  PendingHands hands;              // fits only: resolved by resolveFitHands()
  std::vector<std::string> notes;  // for the user: what was assumed or averaged, one line each
  std::string source_layout;       // the table row that read it ("amass", "fit", ...)
  MemoryCharge charge;             // `frames` and `translation` against the memory budget
};

// Frees the per-frame arrays of `m` (frames, translation, DMPL and expression
// coefficients, the frame changes) and their memory charge, once an export
// has baked them; the rest (name, rate, betas, notes) stays.
void releaseFrames(Motion* m);

// Which parameters of a tool that writes both a world and a camera version
// (WHAM pose_world/pose, GVHMR smpl_params_global/incam, TRAM with or without
// camera.npy) a layout reads: --source-params. Default: the layout's
// preference (the world one).
enum class SourceParams { Default, Global, Incam };

// Options of loadMotion.
struct MotionOptions {
  // --source-fps: the source rate; none = the stored rate, else the layout's
  // default (30 fps; AIST++ 60, as documented) with a note
  std::optional<double> source_fps;
  bool up_given = false;  // --up was given: no note about the layout's default world turn
  SourceParams source_params = SourceParams::Default;  // --source-params global|incam
  // Set by loadMotionSequence (motion_sequence.h): the file is one frame of a
  // --motion-sequence, so a layout whose rows are that frame's hands (HaMeR)
  // reads each row as a track instead of as a frame.
  bool frame_file = false;
  // Folders of per-frame files (loadMotionSequence): an entry named like a
  // frame that cannot be read or numbered is skipped with a note naming it
  // instead of failing the folder (--skip-bad-frames), and a gap between two
  // frame numbers may hold at most this many copies of the frame before it
  // (--max-held-frames N; kMaxHeldFramesLimit at most).
  bool skip_bad_frames = false;
  int64_t max_held_frames = 1000;
};

// The largest --max-held-frames: 100,000 held SMPL-X frames are ~0.4 GB of
// rotations, an hour of video at 30 fps without a detection.
constexpr int64_t kMaxHeldFramesLimit = 100000;

// What one file holds: one Motion per person or track (most files hold one)
// and the notes that concern the file as a whole.
struct MotionSet {
  std::vector<Motion> tracks;
  std::vector<std::string> notes;
  SceneCamera camera;  // the camera the tracks were seen from, when the file has one
};

// Every track of the file at `path` (which names it in errors), each named
// after the file's stem, its frame rate settled (MotionOptions) and its
// values checked (validate_inputs.h). Errors: unreadable file, no pose data,
// an unknown layout, wrong shapes, NaN/Inf; one line naming the file. A file
// with no track is an error, except one frame of a --motion-sequence
// (options.frame_file: a Multi-HMR image without a person), which may be empty.
Result<MotionSet> loadMotionSet(const std::string& path,
                                const MotionOptions& options = MotionOptions());

// The same for a motion given as data, not as a file (the Python module's
// dict of arrays): `root` as a container reader builds it (a Dict; leaves
// widened to double, core/data_node.h), `containers` the ContainerBits
// (motion_layout.h) it may stand for: kNpzFile for a flat dict of arrays (the
// row's keys are decoded, as from np.savez of that dict), others for a
// nested one (a torch.save'd dict). `path` names it in errors and names the
// tracks (its stem). Same rows, decode, rate and checks as loadMotionSet.
Result<MotionSet> loadMotionSetFromTree(DataNode root, unsigned containers, const std::string& path,
                                        const MotionOptions& options = MotionOptions());

// The file's first track, with the file's notes first among its notes.
Result<Motion> loadMotion(const std::string& path, const MotionOptions& options = MotionOptions());

// False for a readable file without pose keys (a shape file); an error if
// the file cannot be read at all.
Result<bool> hasPoseData(const std::string& path);

}  // namespace smpl
