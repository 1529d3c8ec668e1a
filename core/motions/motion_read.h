// A motion file's container, read by content (not by extension,
// core/io/tree/data_tree.h sniffContainer), and the motion layout
// (core/motions/motion_layout.h) its keys call for:
//   .npz (np.savez; SMPLCodec .smpl)   only the member NAMES decide the layout,
//                                      then only that layout's keys are decoded
//                                      (object members as trees)
//   pickle, joblib (plain, zlib, gzip), torch .pt, .npy (numeric or an
//   np.save'd object), JSON            the whole file as a tree (data-only
//                                      readers: nothing is executed)
#pragma once

#include <string>

#include "core/data_node.h"
#include "core/motions/motion_layout.h"
#include "core/motions/unread_keys.h"
#include "core/result.h"

namespace smpl {

struct MotionFile {
  unsigned container = 0;  // a ContainerBits value
  // The file's contents: for an .npz with a layout, that layout's keys
  // decoded; without one (or from probeMotionFile), every member name as a
  // None node. Other containers: the whole tree (the root may be a Dict, a
  // List (EasyMocap) or an Array (a plain .npy)).
  DataNode root;
  const MotionLayout* layout = nullptr;  // null: no row matches
  // An .npz's members outside the row's keys (never decoded), with their
  // shapes: the ignored-keys note names the pose-like ones.
  std::vector<UndecodedMember> undecoded;
};

// The container, read, and its layout. Errors: the file cannot be read or
// is not a container we read (one line naming the file).
Result<MotionFile> readMotionFile(const std::string& path);

// The same, except that an .npz is not decoded at all (member names only):
// enough to tell a motion from a shape file (batch mode).
Result<MotionFile> probeMotionFile(const std::string& path);

}  // namespace smpl
