// An .npz as a DataNode tree: np.savez of a dict whose values are objects
// (ROMP/BEV's video_results.npz keeps everything in one object member,
// `results`). Numeric and text members become Array leaves (NpzArchive::get);
// object members ('|O', a pickle inside the .npy) become trees by the
// data-only unpickler (parseNpyTree, core/io/pickle/pickle_tree.h). Lazy as
// NpzArchive: only the members asked for are inflated or decoded.
#pragma once

#include <string>
#include <vector>

#include "core/data_node.h"
#include "core/io/npz.h"
#include "core/result.h"

namespace smpl {

// A Dict of the members `keys` names (member names without ".npy"), in that
// order; absent keys are left out (the caller decides what is required).
// Empty `keys`: every member, in archive order. Errors name the archive and
// the member: "video_results.npz/results.npy: unknown pickle opcode 0xff at byte 12".
Result<DataNode> readNpzTree(const NpzArchive& npz, const std::vector<std::string>& keys = {});

}  // namespace smpl
