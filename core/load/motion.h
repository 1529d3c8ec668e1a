// Pose sequences, recognised by their keys (not by the extension):
//   AMASS .npz (SMPL-H release: poses (T,156); SMPL-X release: poses (T,165)
//   or the split keys root_orient/pose_body/pose_hand/pose_jaw/pose_eye),
//   SMPL (T,72), plain .npz / .json with `poses` as axis-angle (T,3J) /
//   (T,J,3) or rotation matrices (T,J,3,3); frame rate from
//   `mocap_framerate`, `mocap_frame_rate` or `fps`;
//   Meshcapade SMPLCodec `.smpl` (motion_smplcodec.h);
//   SMPL-X / SMPL fits as fitters write them, .pkl or .npz (motion_fit.h);
//   AIST++ .pkl (motion_aist.h).
// The container is chosen by content: zip magic -> npz, pickle opcodes ->
// data-only unpickler, else JSON. Every frame is validated (finite numbers,
// consistent lengths) before anything is exported.
// A file with no pose keys at all (AMASS `shape.npz`, `*_stagei.npz`, a
// shape-only .smpl) is "no pose data": loadMotion fails on it and
// hasPoseData() says so without failing (batch mode skips such files).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/array.h"
#include "core/body_model.h"
#include "core/math/forward.h"
#include "core/memory_budget.h"
#include "core/result.h"

namespace smpl {

// Hand poses of a fit that need the model to become rotations: PCA
// coefficients of the model's hands_components, and/or axis-angle poses to
// which the model's hands_mean is added (motion_fit.h). Empty otherwise.
struct PendingHands {
  std::vector<Eigen::VectorXd> left, right;  // T entries of C values each (C = 45: full pose)
  bool active() const { return !left.empty() || !right.empty(); }
};

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
                              // error of an export that needs them (core/load/dmpl.h)
  bool amass = false;         // AMASS-style file (Z-up world)
  PendingHands hands;         // fits only: resolved by resolveFitHands()
  std::vector<std::string> notes;  // for the user: what was assumed or averaged, one line each
  MemoryCharge charge;             // `frames` and `translation` against the memory budget
};

// Options of loadMotion.
struct MotionOptions {
  double source_fps = 0.0;     // --source-fps: the source rate; 0 = stored rate, else a default
  double fps_fallback = 30.0;  // rate assumed when none is stored (AIST++: 60, as documented)
};

// `path` names the file in errors. Errors: unreadable file, no pose data,
// wrong shapes, NaN/Inf.
Result<Motion> loadMotion(const std::string& path, const MotionOptions& options);
Result<Motion> loadMotion(const std::string& path, double fps_fallback = 30.0);

// The file's arrays (npz, pickle or JSON by content).
Result<ArrayDict> readMotionArrays(const std::string& path);

// False for a readable file without pose keys (a shape file); an error if
// the file cannot be read at all.
Result<bool> hasPoseData(const std::string& path);

}  // namespace smpl
