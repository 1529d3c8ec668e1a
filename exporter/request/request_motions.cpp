#include "exporter/request/request_motions.h"

#include <atomic>

#include "core/load/motion_fit.h"

namespace smpl {
namespace {

std::atomic<uint64_t> decoded{0};

}  // namespace

Result<Motion> decodeMotion(const std::string& path, const ExportRequest& request) {
  ++decoded;
  MotionOptions options;
  options.source_fps = request.source_fps.value_or(0.0);
  options.up_given = request.up != UpAxis::Auto;  // no note about the layout's default turn
  return loadMotion(path, options);
}

Status resolveMotionHands(const BodyModel& model, const ExportRequest& request,
                          const std::string& path, Motion* motion) {
  return resolveFitHands(model, request.flat_hand_mean, path, motion);
}

uint64_t motionsDecoded() { return decoded.load(); }

}  // namespace smpl
