// The skin weights an export writes (--skin-weights, --max-influences):
// either the model's weights truncated to the M largest per vertex and
// renormalised (core/math/skin_weights.h), or weights fitted to reproduce the
// unpruned model over training poses (core/math/skin_weight_fit.h). Both the
// pipeline and the error report of the summary line call this, so they agree.
#pragma once

#include "core/body_model.h"
#include "core/math/forward.h"
#include "core/math/skin_weights.h"
#include "exporter/export_options.h"

namespace smpl {

// M for `options` on `model`: --max-influences N clamped to the K joints,
// kAllInfluences -> K. The clamp is a precondition: the request refuses N
// outside 1..K first (request/check_request.h, the one check).
int influencesFor(const BodyModel& model, const ExportOptions& options);

// N x M skin of the subject `body` (shapeBody of the export's betas). With
// kAllInfluences, M is the largest number of non-zero weights of any vertex.
SparseSkin exportSkin(const BodyModel& model, const ShapedBody& body, const ExportOptions& options);

// "truncated" / "optimized".
const char* skinWeightMethodName(SkinWeightMethod method);

}  // namespace smpl
