// AIST++ motion files (.pkl, as the AIST++ API reads them):
//   smpl_poses    (T,72) SMPL axis-angle, root first
//   smpl_trans    (T,3)  root translation in the scaled world
//   smpl_scaling  (1,)   the body's scale factor
//   smpl_loss     ignored
// The body in AIST++ is the SMPL body scaled by smpl_scaling about the
// origin; our export keeps the model's size, so the translation is
// smpl_trans / smpl_scaling (metres), as the AIST++ API does before its SMPL
// forward pass. AIST++ stores no frame rate; its documentation gives 60 fps
// (assumed with a note unless --source-fps says otherwise). Y-up world.
#pragma once

#include <string>

#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/motions/motion_layout.h"
#include "core/result.h"

namespace smpl {
namespace motion_detail {

// The row's decode for files with `smpl_poses`; fps is left 0.
Status decodeAist(const DataNode& d, const std::string& path, Motion* m);

}  // namespace motion_detail

// The table row (core/motions/motion_layout.h): matches `smpl_poses`; 60 fps assumed
// (AIST++'s documented rate) when no --source-fps is given.
const MotionLayout& aistLayout();

}  // namespace smpl
