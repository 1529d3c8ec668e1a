// The one place an export reads its motions (issue 27 item 1): each motion
// file is opened and decoded once per export, and that decoded Motion serves
// every later step (the --model DIR pick, the fit hands, the betas, DMPL, the
// bake). Two small functions, so the motion reader (core/load/motion.h) can be
// swapped behind them.
#pragma once

#include <cstdint>
#include <string>

#include "core/body_model.h"
#include "core/load/motion.h"
#include "core/result.h"
#include "exporter/request/export_request.h"

namespace smpl {

// loadMotion(path) with the request's --source-fps. Errors name the file.
Result<Motion> decodeMotion(const std::string& path, const ExportRequest& request);

// Fit hand poses (PCA coefficients, hands_mean) through `model`'s basis, with
// the request's --flat-hand-mean (core/load/motion_fit.h resolveFitHands).
// A no-op for motions without pending hands; errors name the motion `path`.
Status resolveMotionHands(const BodyModel& model, const ExportRequest& request,
                          const std::string& path, Motion* motion);

// How many times decodeMotion ran in this process (every thread): the test
// hook that shows a motion is decoded once per export.
uint64_t motionsDecoded();

}  // namespace smpl
