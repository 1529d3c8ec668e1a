// The motion reader table (motion_layout.h): every layout, in detection
// order, and what is derived from it.
#include <algorithm>
#include <cctype>

#include "core/docs_location.h"
#include "core/io/printable.h"
#include "core/motions/motion_aist.h"
#include "core/motions/motion_amass.h"
#include "core/motions/motion_bare_poses.h"
#include "core/motions/motion_beat2.h"
#include "core/motions/motion_easymocap.h"
#include "core/motions/motion_fit.h"
#include "core/motions/motion_gvhmr.h"
#include "core/motions/motion_hamer.h"
#include "core/motions/motion_layout.h"
#include "core/motions/motion_mcs.h"
#include "core/motions/motion_mdm.h"
#include "core/motions/motion_mhr.h"
#include "core/motions/motion_motionx.h"
#include "core/motions/motion_multihmr.h"
#include "core/motions/motion_phalp.h"
#include "core/motions/motion_positions.h"
#include "core/motions/motion_prompthmr.h"
#include "core/motions/motion_romp.h"
#include "core/motions/motion_smplcodec.h"
#include "core/motions/motion_smplerx.h"
#include "core/motions/motion_tram.h"
#include "core/motions/motion_vibe.h"
#include "core/motions/motion_vposer.h"
#include "core/motions/motion_wham.h"
#include "core/motions/unread_keys.h"

namespace smpl {

const std::vector<MotionLayout>& motionLayouts() {
  // Order: a layout whose keys another layout's files may also carry comes after it.
  static const std::vector<MotionLayout> table = {
      mhrLayout(),        // SAM 3D Body / MHR (refused), first: its dicts may carry any key
      smplCodecLayout(),  // bodyPose (.smpl)
      motionxLayout(),    // a (T,322) / (T,172) array (.npy)
      positionsLayout(),  // joint positions (refused): (T,22,3) arrays, MDM results.npy
      barePosesLayout(),  // a bare (T,3K) / (T,K,3) / (T,K,3,3) pose array, after Motion-X's widths
      mdmLayout(),        // motion + thetas (MDM smpl_params .npy)
      aistLayout(),       // smpl_poses
      vposerLayout(),  // latent_pose, pose_embedding, latent (refused) before AMASS's root_orient
      beat2Layout(),   // poses + expressions / model, before AMASS's poses
      gvhmrLayout(),   // smpl_params_global / smpl_params_incam dicts
      whamLayout(),    // per-track dicts with pose, trans, frame_ids
      vibeLayout(),    // per-person dicts with pose, frame_ids, orig_cam, no trans
      phalpLayout(),   // per-frame dicts with tid, tracked_time, smpl
      tramLayout(),    // pred_rotmat, pred_trans, frame (.npy of tensors)
      rompLayout(),    // .npz members results + sequence_results (ROMP, BEV)
      promptHmrLayout(),  // people dicts with smplx_world / smplx_cam (results.pkl)
      multiHmrLayout(),   // rotvec + transl_pelvis (per-image npz)
      mcsLayout(),        // glTF JSON with MC_scene_description (.mcs)
      easymocapLayout(),  // a JSON list of persons with Rh, Th, poses
      smplerxLayout(),    // exactly SMPLer-X's ten fit keys, before the fit row
      amassLayout(),      // poses, root_orient
      hamerLayout(),      // hand_pose + global_orient, no body_pose: before the fit's global_orient
      fitLayout(),        // body_pose, global_orient
  };
  return table;
}

const MotionLayout* findLayout(const DataNode& root, unsigned container) {
  for (const MotionLayout& row : motionLayouts())
    if ((row.containers & container) && row.matches(root)) return &row;
  return nullptr;
}

std::vector<std::string> motionFileExtensions() {
  unsigned containers = 0;
  for (const MotionLayout& row : motionLayouts()) containers |= row.containers;
  std::vector<std::string> out;
  if (containers & kNpzFile) out.insert(out.end(), {".npz", ".smpl"});
  if (containers & (kPickleFile | kJoblibFile)) out.push_back(".pkl");
  if (containers & kJoblibFile) out.push_back(".joblib");
  if (containers & kTorchFile) out.insert(out.end(), {".pt", ".pth"});
  if (containers & kNpyFile) out.push_back(".npy");
  if (containers & kJsonFile) out.insert(out.end(), {".json", ".mcs"});  // .mcs: Meshcapade scenes
  return out;
}

namespace {

// The keys, sorted, comma-separated, at most 12 then ", ...".
std::string keyList(const DataNode& root) {
  std::vector<std::string> keys = root.keys;
  std::sort(keys.begin(), keys.end());
  std::string list;
  const size_t shown = std::min<size_t>(keys.size(), 12);
  for (size_t i = 0; i < shown; ++i) list += (i ? ", " : "") + printable(keys[i], 64);
  if (keys.size() > shown) list += ", ... (" + std::to_string(keys.size()) + " keys)";
  return list.empty() ? "none" : list;
}

}  // namespace

// A shape file holds a betas key (betas, shape, shapeParameters) and nothing
// that looks like pose data (AMASS shape.npz, *_stagei.npz, a shape-only .smpl).
bool isShapeOnly(const DataNode& root) {
  if (!root.isDict()) return false;
  bool betas = false;
  for (const std::string& key : root.keys) {
    if (looksLikePose(key)) return false;
    betas |= key == "betas" || key == "shape" || key == "shapeParameters";
  }
  return betas;
}

// The arrays every SMPL-family model file carries (the authors' releases):
// a template mesh with its blend shapes or skin.
bool isBodyModel(const DataNode& root) {
  if (!root.isDict()) return false;
  bool templ = false, blend = false;
  for (const std::string& key : root.keys) {
    templ |= key == "v_template";
    blend |= key == "shapedirs" || key == "posedirs" || key == "weights" || key == "J_regressor";
  }
  return templ && blend;
}

std::string unmatchedMessage(const DataNode& root) {
  if (!root.isDict())
    return "holds " + describeNode(root) +
           " at the top level; not a motion layout this version reads (supported layouts: " +
           docsPageReference("motions.md") + ")";
  if (isBodyModel(root))
    return "a body model file (keys " + keyList(root) +
           "), not a motion: give it as --model, and the motion as --motion";
  if (isShapeOnly(root))
    return "no pose data (keys " + keyList(root) +
           "): a shape file, not a motion: give it as --betas-file";
  return "keys found: " + keyList(root) + "; supported layouts: " + docsPageReference("motions.md");
}

}  // namespace smpl
