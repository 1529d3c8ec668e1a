// GVHMR results (zju3dv/GVHMR tools/demo/demo.py: torch.save(pred,
// "hmr4d_results.pt"); hmr4d/model/gvhmr/gvhmr_pl_demo.py DemoPL.predict), or
// the same nested dict pickled with numpy arrays:
//   smpl_params_global  {body_pose (L,63), betas (L,10), global_orient (L,3),
//                        transl (L,3)}: the gravity-aligned "ay" frame, Y up
//   smpl_params_incam   the same in the camera frame
//   K_fullimg (L,3,3), net_outputs {...}  not read
// --source-params global (default) reads smpl_params_global (note "world
// frame ('smpl_params_global'; Y up)"); incam reads smpl_params_incam (camera
// frame, --up -y). A file with only one of them uses it by default.
// Body model (hmr4d/utils/smplx_utils.py make_smplx("supermotion"),
// hmr4d/utils/body_model/body_model_smplx.py): SMPL-X neutral, 10 betas,
// num_pca_comps=12, flat_hand_mean=False. GVHMR passes no hand pose, so the
// zero PCA coefficients plus smplx's pose_mean put each hand at the model's
// hands_mean: 45 zeros per frame go to Motion::hands (resolveFitHands adds
// the mean; a model without hands_mean keeps the hands at rest with a note).
// Jaw, eyes and expression zero; transl is the SMPL-X transl. Betas: the
// mean of the L rows (note). No rate stored: 30 fps. One person.
// Detected by content: a dict with a `smpl_params_global` or
// `smpl_params_incam` dict. Wrong shapes name the key path:
//   "<file>: 'smpl_params_global/body_pose' has shape (24,60); expected (24,63)".
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& gvhmrLayout();

}  // namespace smpl
