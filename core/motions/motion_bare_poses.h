// Bare pose arrays: a file whose only content is one numeric pose array, no
// dict and no keys (.npy by np.save, .pt by torch.save of a tensor, a pickle
// or joblib dump of an array). Shapes, K a family's joint count (24 SMPL,
// 52 SMPL-H, 55 SMPL-X, 16 MANO):
//   (T,3K) or (T,K,3)  axis-angle
//   (T,K,3,3)          rotation matrices
// Read exactly as the AMASS row reads its `poses` (motion_amass.h
// decodeRotations): the model's joint order (SMPL-X: smplx full_pose order,
// root, 21 body, jaw, left eye, right eye, 15 left-hand, 15 right-hand),
// finger rotations absolute. The file holds no translation (zeros), no betas
// and no rate (30 fps assumed, with a note); a Y-up world, as the other rows
// whose files do not say.
// Example: MHR's tools/smpl_mhr_conversion/data/example_smplx_poses.npy
// (facebookresearch/MHR), an (8,165) SMPL-X pose array; its example.py slices
// body 3:66 and hands -90:-45 / -45: and poses smplx.SMPLX(use_pca=False,
// flat_hand_mean=True) with them.
// A (T,24,3) array may be SMPL's 24 joint positions instead: when the
// distances from joint 0 to joints 1, 2 and 3 stay constant over the frames
// (rigid bones of 2 to 50 cm), it is refused as positions, as the positions
// row (motion_positions.h) refuses them.
// Detection: the root is a numeric array of one of the shapes above.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& barePosesLayout();

}  // namespace smpl
