// Files that hold joint positions, not rotations: a body cannot be posed from
// them without fitting one first, so they are refused with what to do.
//   MDM results.npy (GuyTevet/motion-diffusion-model sample/generate.py:
//     np.save of {'motion' (N,J,3,T) joint positions (rot2xyz with
//     jointstype='smpl' for every model), 'text', 'lengths', 'num_samples',
//     'num_repetitions'}, J = 22 HumanML3D, 21 KIT, 24 SMPL)
//   HumanML3D / KIT joints (EricGuo5513/HumanML3D motion_representation:
//     new_joints/<id>.npy (T,22,3) or (T,21,3))
//   HumanML3D / KIT features (new_joint_vecs/<id>.npy (T,263) or (T,251):
//     root velocities, joint positions and velocities, 6D rotations that are
//     not the body's (relative to a canonical skeleton), foot contacts)
// Detection: a dict with `motion` and any of `lengths`, `num_samples`,
// `num_repetitions`, and no `thetas` (MDM's smpl_params file has `thetas`);
// or a numeric array root of one of the shapes above.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& positionsLayout();

}  // namespace smpl
