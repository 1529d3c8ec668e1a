// The DMPL part of one export (issue 14, exporter/dmpl_targets.h): resolve
// --dmpl (a file, or a folder searched by the motion's gender), check the
// motions' `dmpls` against the basis, add the dmpl_<i> targets with the
// encoding taken from the motions' range, and the notes the user needs
// (no `dmpls` in the motion; `dmpls` present but no --dmpl; the measured cost
// of fixed joints, after baking).
#pragma once

#include <string>
#include <vector>

#include "cli/export_job.h"
#include "core/body_model.h"
#include "core/load/motion.h"
#include "exporter/asset.h"

namespace smpl {

// Before baking. Errors (ErrorKind::Load, exit 2: basis or coefficients
// unusable) are one "Error loading <file>: ..." line.
Status addDmplToAsset(const BodyModel& model, const Settings& s, const ExportJob& job, const std::vector<Motion>& motions,
                      Asset* asset, ExportReport* report);

// After baking: one note per clip with the fixed-joint cost (max vertex error, mm).
void noteDmplJointCost(const Asset& asset, ExportReport* report);

}  // namespace smpl
