// The export pipeline: model + options -> format-neutral Asset (asset.h).
// Every number a writer serialises is computed here, once, so the glTF and FBX
// files of one export carry the same content. The options themselves are
// exporter/export_options.h.
//
//   Result<Asset> asset = buildAsset(model, options);
//   const Writer* w = writerForPath("body.glb");  // writers/writer.h
#pragma once

#include <string>

#include "core/body_model.h"
#include "core/result.h"
#include "exporter/asset.h"
#include "exporter/export_options.h"

namespace smpl {

class SkinCache;  // exporter/skin_cache.h

// The rest asset: skeleton, mesh, skin (exportSkin), morph targets. The
// options' ranges are checked before, once, by the request
// (request/check_request.h checkRequestForModel); here they are
// preconditions: counts beyond the model are clamped (max_influences by
// influencesFor, shape/expression keys to B/E), a corrective basis without
// correctives is not built, and a basis with Split weights is signed. Errors:
// more betas or expression values than the model has (shapeBody), an
// unreadable --uv file (kind Load), a basis that cannot be fitted. With
// options.mesh false: the skeleton and metadata only (Asset::skeleton_only).
// `skins` (optional): the skin and refit of a subject exported before with
// the same model, betas and skin options are taken from it, not fitted again
// (exporter/skin_cache.h); `model` must then outlive the cache.
Result<Asset> buildAsset(const BodyModel& model, const ExportOptions& options,
                         SkinCache* skins = nullptr);

// Morph target name for pose feature n: pose_<joint>_<r><c> (docs/file-contract.md).
std::string correctiveTargetName(const BodyModel& model, int feature);

}  // namespace smpl
