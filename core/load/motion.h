// Pose sequences: AMASS .npz (SMPL-H release: poses (T,156); SMPL-X release:
// poses (T,165) or the split keys root_orient/pose_body/pose_hand/pose_jaw/
// pose_eye), SMPL (T,72), and plain .npz / .json with `poses` as axis-angle
// (T,3J) / (T,J,3) or rotation matrices (T,J,3,3). Frame rate from
// `mocap_framerate`, `mocap_frame_rate` or `fps`. Every frame is validated
// (finite numbers, consistent lengths) before anything is exported.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/math/forward.h"
#include "core/memory_budget.h"
#include "core/result.h"

namespace smpl {

struct Motion {
  std::string name;                 // file stem
  ModelKind layout = ModelKind::Smpl;  // joint layout of `rotations`
  double fps = 30.0;
  std::vector<Rotations> frames;    // T x J local rotations, source layout order
  std::vector<Eigen::Vector3d> translation;  // T root translations (`trans`; zeros if absent)
  std::vector<double> betas;        // empty if the file has none
  std::string gender;               // "" if absent
  bool amass = false;               // AMASS-style file (Z-up world)
  std::vector<std::string> notes;   // for the user, e.g. per-frame betas averaged
  MemoryCharge charge;              // `frames` and `translation` against the memory budget
};

// `path` names the file in errors. fps_fallback is used when the file has no rate.
Result<Motion> loadMotion(const std::string& path, double fps_fallback = 30.0);

}  // namespace smpl
