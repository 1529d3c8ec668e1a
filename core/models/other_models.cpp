// Names STAR, SUPR and SKEL model files from their arrays (other_models.h).
#include "core/models/other_models.h"

#include <algorithm>

namespace smpl {
namespace {

bool has(const std::vector<std::string>& keys, const char* key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// The joint count: kintree_table's columns, else weights' columns; 0 when
// neither is a 2-D array.
int64_t jointCount(const ArrayDict& arrays) {
  for (const char* key : {"kintree_table", "weights"}) {
    auto it = arrays.find(key);
    if (it != arrays.end() && it->second.shape.size() == 2) return it->second.shape[1];
  }
  return 0;
}

// posedirs' feature count (its last axis: (N,3,F) or (3N,F)), or -1.
int64_t poseFeatures(const ArrayDict& arrays) {
  auto it = arrays.find("posedirs");
  if (it == arrays.end() || it->second.shape.size() < 2) return -1;
  return it->second.shape.back();
}

bool suprJointRegressor(const ArrayDict& arrays, int64_t k) {
  auto jr = arrays.find("J_regressor");
  auto vt = arrays.find("v_template");
  if (jr == arrays.end() || vt == arrays.end() || jr->second.shape.size() != 2) return false;
  if (vt->second.shape.empty()) return false;
  return jr->second.shape[0] == 3 * k && jr->second.shape[1] == 3 * vt->second.shape[0] + 1;
}

std::string refusal(const std::string& path, const std::string& what, const std::string& why) {
  return path + ": " + what + ", not an SMPL-family model (" + why +
         "); this version exports SMPL, SMPL-H, SMPL-X and MANO: give the SMPL-family model file "
         "of "
         "the body (docs/motions.md \"Models that are not SMPL\")";
}

}  // namespace

Status refuseOtherModel(const std::vector<std::string>& keys, const ArrayDict& arrays,
                        const std::string& path) {
  if (has(keys, "skin_template_v") || has(keys, "J_regressor_osim") ||
      has(keys, "osim_kintree_table"))
    return makeError(refusal(path, "a SKEL model file",
                             "skin_template_v, J_regressor_osim: SKEL's anatomical skeleton with "
                             "46 pose parameters"));
  const int64_t k = jointCount(arrays), features = poseFeatures(arrays);
  if (k > 1 && features == 4 * (k - 1) + 1)
    return makeError(refusal(path, "a STAR model file",
                             "'posedirs' has " + std::to_string(features) +
                                 " quaternion pose features; SMPL's have 9 per joint"));
  if (has(keys, "axis_meta") || (k > 1 && features == 4 * k) || suprJointRegressor(arrays, k))
    return makeError(refusal(path, "a SUPR model file",
                             "quaternion pose features and a joint regressor with a bias column "
                             "for " +
                                 std::to_string(k) + " joints"));
  return Status();
}

}  // namespace smpl
