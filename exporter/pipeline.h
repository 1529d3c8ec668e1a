// The export pipeline: model + options -> format-neutral Asset (asset.h).
// Every number a writer serialises is computed here, once, so the glTF and FBX
// files of one export carry the same content.
//
//   Result<Asset> asset = buildAsset(model, options);
//   const Writer* w = writerForPath("body.glb");  // plugins/writer.h
#pragma once

#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

struct ExportOptions {
  std::vector<double> betas;       // zero-padded to the model's count; more is an error
  std::vector<double> expression;  // SMPL-X only
  int max_influences = 4;
  bool correctives = true;         // one morph target per pose feature
  int shape_keys = 0;              // also export the first N shape directions
  int expression_keys = 0;         // also export the first N expression directions
  std::string uv_obj;              // optional OBJ with UVs in the model's vertex order
  std::string name = "body";
};

Result<Asset> buildAsset(const BodyModel& model, const ExportOptions& options);

// Morph target name for pose feature n: pose_<joint>_<r><c> (DESIGN.md).
std::string correctiveTargetName(const BodyModel& model, int feature);

}  // namespace smpl
