// EasyMocap SMPL results (zju3dv/EasyMocap easymocap/mytools/file_utils.py
// write_smpl -> write_common_results): one JSON per frame, `000012.json`,
// a list of persons
//   {"id": 0, "Rh": [[3]], "Th": [[3]], "poses": [[72]], "shapes": [[10]]}
// (each array one row; numbers written '%2.3f', rows joined by "\r\n").
// Body model (easymocap/smplmodel/body_model.py SMPLlayer.forward,
// easymocap/bodymodel/smpl.py): vertices = LBS(poses, shapes) Rodrigues(Rh)^T
// + Th, i.e. Rh turns the posed body about the model's origin (not the
// pelvis) and `poses[:3]` (written as zero) is the root's own rotation:
// Motion::world_rotation = Rodrigues(Rh), world_translation = Th, the root
// Rodrigues(poses[:3]), translation zero. The world is the calibration
// board's, Z up (apps/calibration/detect_chessboard.py getChessboard3d):
// MotionWorld::Z (--up z; note). Persons by `id` (tracks). A folder is a
// --motion-sequence (motion_sequence.h); a single file is a one-frame motion
// of its persons at the frame its name gives. SMPL-H / SMPL-X results
// (`handl`, `handr`, `expression`, or `poses` of 78 / 87 values: the PCA
// layouts of NUM_POSES) are refused, naming the keys. --source-params incam
// is refused (no camera-frame parameters). No rate stored: 30 fps.
// Detected by content: a JSON list of objects with `Rh`, `Th` and `poses`.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& easymocapLayout();

}  // namespace smpl
