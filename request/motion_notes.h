// What the user is told about the motions of an export, produced once, from
// what the bake used: each motion's own notes (assumed rates, averaged
// betas, ...), the --frames range clamped to a shorter motion, and the
// motion joints the mapping dropped (AnimationClip::dropped_joints).
#pragma once

#include <string>
#include <vector>

#include "core/motions/motion.h"
#include "exporter/animation.h"
#include "exporter/asset.h"
#include "request/export_request.h"

namespace smpl {

// --frames A:B for `motion`, its end clamped to the motion's length; `note`
// (if not null) gets the line saying so, or stays empty.
AnimationOptions framesFor(const AnimationOptions& animation, const Motion& motion,
                           std::string* note);

// Appends to report->notes, per motion i in order: motions[i].notes (a
// "betas:" note only for the first motion and only when `betas_given` is
// false, where those betas are used), frame_notes[i] (framesFor) and the
// joints asset.animations[i] dropped; adds the clips' frames to report->frames.
void noteMotions(const std::vector<Motion>& motions, const std::vector<std::string>& frame_notes,
                 bool betas_given, const Asset& asset, ExportReport* report);

}  // namespace smpl
