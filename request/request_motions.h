// The one place an export reads its motions: each motion
// file (or --motion-sequence folder) is opened and decoded once per export,
// and that decoded Motion serves every later step (the --model DIR pick, the
// fit hands, the betas, DMPL, the bake). Small functions, so the motion
// reader (core/motions/motion.h) stays behind them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/motions/motion_tracks.h"
#include "core/result.h"
#include "request/export_request.h"

namespace smpl {

// Every track of `path` (a motion file, or the request's --motion-sequence
// folder, core/motions/motion_sequence.h) with the request's --source-fps,
// --source-params and --up. A folder given as --motion is refused (what to
// give instead). Errors name the file.
Result<MotionSet> decodeMotionSet(const std::string& path, const ExportRequest& request);

// The one track the request's --track picks (longest or an id; `all` is the
// caller's: one export per track), with its notes. Errors: an unknown id.
Result<Motion> decodeMotion(const std::string& path, const ExportRequest& request);

// The same for a motion given as data (the Python module's dict of arrays,
// core/motions/motion.h loadMotionSetFromTree): `root` read as np.savez of it
// when it is a flat dict of arrays (as `.npz`), else as a torch.save'd or
// pickled tree; `name` names it in errors and is the clip's name (its stem).
Result<Motion> decodeMotionTree(DataNode root, const std::string& name,
                                const ExportRequest& request);

// Fit hand poses (PCA coefficients, hands_mean) through `model`'s basis, with
// the request's --flat-hand-mean (core/motions/motion_fit.h resolveFitHands).
// A no-op for motions without pending hands; errors name the motion `path`.
Status resolveMotionHands(const BodyModel& model, const ExportRequest& request,
                          const std::string& path, Motion* motion);

// `out` for track `id` of --track all: DIR/walk.glb -> DIR/walk.track<id>.glb,
// the id (which comes from the motion file) made one safe file-name component
// by safeNameComponent() (core/io/name_component.h): "a/b" -> walk.tracka%2Fb.glb.
std::string trackOutput(const std::string& out, const std::string& id);

// How many times decodeMotionSet ran in this process (every thread): the test
// hook that shows a motion is decoded once per export.
uint64_t motionsDecoded();

}  // namespace smpl
