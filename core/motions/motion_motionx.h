// Motion-X whole-body SMPL-X motions (IDEA-Research/Motion-X; HumanTOMATO):
// `motion_data/smplx_322/<subset>/<clip>.npy`, one numeric array saved with
// np.save (float32 in the release), one row per frame. Columns, as
// mocap-dataset-process/humanml.py get_smplx_322 concatenates them and
// tomato_represenation/smplx2joints.py process_smplx_322_data slices them:
//   (T,322)  0:3 root (joint 0), 3:66 body (joints 1-21), 66:111 left hand
//            (SMPL-X joints 25-39), 111:156 right hand (40-54), 156:159 jaw (22),
//            159:209 face expression psi 0..49, 209:309 face shape (FLAME, no
//            SMPL-X counterpart: ignored, noted when non-zero), 309:312 trans,
//            312:322 betas
//   (T,172)  0:159 the same, 159:162 trans, 162:172 betas (no face columns)
// Conventions (visualization/render_world_space_motion.py: SMPLX(use_pca=False,
// flat_hand_mean=True), eyes zero): axis-angle; the hands absolute (nothing is
// added); eyes at rest; v = LBS(...) + trans (smplx `transl`); a Y-up world
// (humanml.py process_pose turns AMASS's Z up into Y up); betas per frame
// (the betas-rows rule, core/models/betas_rows.h); no rate stored: the README's
// "unified in 30 fps". One person. Expression coefficients are baked with
// --expression-keys (Motion-X's renderer uses the first 10).
// Detection: the file's root is a 2-D array whose width is 322 or 172.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& motionxLayout();

}  // namespace smpl
