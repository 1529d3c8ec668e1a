// The safety net after a layout's decode: every array a recognised layout
// carries is read or named in a note. A pose-like array the decode never
// fetched (DataNode::read), or an .npz member outside the row's keys, is
// named once per file:
//   "ignored: smpl_params_global/extra_pose (30,63), 1/extra_pose (20,63) in
//    2 entries (arrays the gvhmr reader does not read)"
// unless a note of the decode already names that key.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/data_node.h"

namespace smpl {

// A key that names pose data in some layout ("poses", "body_pose",
// "pred_rotmat", "smpl_thetas", "global_orient", "joints3d", ...); what
// tells a motion from a shape file (motion_layout.h isShapeOnly).
bool looksLikePose(const std::string& key);

// looksLikePose, or a key of other body data (hand, jaw, eye, expression,
// trans, betas, shape): what must not be dropped silently.
bool looksLikeBodyData(const std::string& key);

// An .npz member left undecoded (not among the row's keys), with its shape.
struct UndecodedMember {
  std::string name;
  std::vector<int64_t> shape;
};

// Clears every node's read mark (a row's `matches` fetches keys too).
void clearReadMarks(const DataNode& root);

// The note naming the pose-like arrays of `root` no decode fetched and the
// pose-like `undecoded` members, or "" when there are none or every one of
// them is already named by one of `notes`. `row` is the layout's name.
std::string unreadKeysNote(const DataNode& root, const std::vector<UndecodedMember>& undecoded,
                           const std::string& row, const std::vector<std::string>& notes);

}  // namespace smpl
