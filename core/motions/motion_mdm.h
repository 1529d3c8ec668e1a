// MDM (text-to-motion, HumanML3D models) rendered to SMPL parameters:
// `sample<i>_rep<j>_smpl_params.npy` from GuyTevet/motion-diffusion-model
// visualize/render_mesh.py (visualize/vis_utils.py npy2obj.save_npy): np.save
// of a dict
//   motion            (25,6,T) float32: rows 0-23 the 24 SMPL joints' 6D
//                     rotations (row 0 the global orient), row 24 =
//                     [root joint position x, y, z, 0, 0, 0]
//                     (visualize/simplify_loc2rot.py joint2smpl)
//   thetas (24,6,T), root_translation (3,T): the same split (read when
//                     `motion` is absent)
//   faces, vertices (a pickled torch tensor), text, length: not read
// 6D (utils/rotation_conversions.py, PyTorch3D): matrix_to_rotation_6d keeps
// the first two ROWS of R; rotation_6d_to_matrix is Gram-Schmidt: b1 = a1/|a1|,
// b2 = (a2 - (b1.a2) b1)/|.|, b3 = b1 x b2, R = rows (b1, b2, b3). Raw network
// 6D (not orthonormal) is read the same way.
// Translation (model/rotation2xyz.py glob=True, translation=True,
// vertstrans=True): SMPL with zero betas and no transl, plus the root
// position relative to frame 0: trans[t] = motion[24,0:3,t] - motion[24,0:3,0].
// SMPL neutral, zero betas (--betas applies), a Y-up world, one person; no
// rate stored: sample/generate.py's 20 fps for HumanML3D.
// Detection: a dict with `motion` and `thetas` or `root_translation`, or with
// `thetas` and `root_translation`.
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/motions/motion_layout.h"
#include "core/result.h"

namespace smpl {

const MotionLayout& mdmLayout();

// PyTorch3D's rotation_6d_to_matrix for one joint: a = (a1, a2), the first
// two rows of R before Gram-Schmidt. Error (naming `what`, e.g. "frame 3
// joint 5") when a1 or a2's part orthogonal to a1 is (nearly) zero.
Result<Eigen::Matrix3d> rotationFrom6d(const double a[6], const std::string& what);

}  // namespace smpl
