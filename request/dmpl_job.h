// The DMPL part of one export (exporter/dmpl_targets.h): resolve
// --dmpl (a file, or a folder searched by the motion's gender), check the
// motions' `dmpls` against the basis, add the dmpl_<i> targets with the
// encoding taken from the motions' range, and the notes the user needs
// (no `dmpls` in the motion; `dmpls` present but no --dmpl; the measured cost
// of fixed joints, after baking).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/motions/motion.h"
#include "exporter/asset.h"
#include "exporter/dmpl_targets.h"
#include "request/export_request.h"

namespace smpl {

// The basis and encoding to hand to exportAsset (input.basis stays null when
// no DMPL targets are wanted). Errors (ErrorKind::Load, exit 2: basis or
// coefficients unusable) are one "Error loading <file>: ..." line.
struct PreparedDmpl {
  std::unique_ptr<DmplBasis> basis;
  DmplInput input;
};
// `motions` are the request's motions, decoded (request.motions[i] names motions[i]).
Result<PreparedDmpl> prepareDmpl(const BodyModel& model, const ExportRequest& request,
                                 const std::vector<Motion>& motions, ExportReport* report);

// After baking: one note per clip with the fixed-joint cost (max vertex error, mm).
void noteDmplJointCost(const Asset& asset, ExportReport* report);

}  // namespace smpl
