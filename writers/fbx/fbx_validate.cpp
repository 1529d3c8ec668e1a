// Input checks of the FBX writer: its own options, then validateAsset (every
// size and index the scene builders rely on, so they can index without bounds
// checks (fbx_scene_internal.h); the same rules as the glTF writer).
#include "exporter/validate_asset.h"
#include "writers/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {

Status validateInput(const Asset& a, const WriterOptions& o) {
  if (o.fbx_units != "m" && o.fbx_units != "cm")
    return makeError("FBX: units '" + o.fbx_units + "'; expected m or cm");
  if (o.fbx_version != 7400 && o.fbx_version != 7500)
    return makeError("FBX: version " + std::to_string(o.fbx_version) + "; expected 7400 or 7500");
  return validateAsset(a);  // the same rules for every writer (exporter/validate_asset.h)
}

}  // namespace fbx
}  // namespace smpl
