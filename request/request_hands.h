// --hands FILE (repeatable) and --hands-wrist: MANO hand tracks (HaMeR,
// WiLoR, any layout the MANO readers read; a folder is read as per-frame
// files, as --motion-sequence reads it) decoded and combined into the body
// clip's fingers (core/motions/combine_hands.h; docs/motions.md "Combining
// hand tracks").
#pragma once

#include <string>

#include "core/body_model.h"
#include "core/motions/motion.h"
#include "core/result.h"
#include "request/export_request.h"

namespace smpl {

// Every track of the request's --hands files put into `body` (read from
// `body_path`, its fit hands already resolved through `model`), with
// --hands-wrist. A no-op without --hands. Errors: one line naming the file
// it is about, which `about` receives (a hand file, the body clip or the
// model): unreadable or hostile hand files, a model or clip without finger
// joints, and the checks of combineHands.
Status applyRequestHands(const BodyModel& model, const ExportRequest& request,
                         const std::string& body_path, Motion* body, std::string* about);

}  // namespace smpl
