// A motion file's container, read by content (not by extension), and the
// motion layout (core/load/motion_layout.h) its keys call for:
//   zip magic "PK"        .npz (and SMPLCodec .smpl): only the member NAMES
//                         decide the layout, then only that layout's keys are
//                         decoded (object members by the data-only unpickler)
//   pickle opcodes        .pkl: the data-only unpickler (never executes)
//   '{' first             .json (or a .json name)
// Anything else is refused with the .npz reader's message (what a zip needs).
#pragma once

#include <string>

#include "core/data_node.h"
#include "core/load/motion_layout.h"
#include "core/result.h"

namespace smpl {

struct MotionFile {
  unsigned container = 0;  // a ContainerBits value
  // The file's keys: for an .npz with a layout, that layout's keys decoded;
  // without one (or from probeMotionFile), every member name as a None node.
  DataNode root;
  const MotionLayout* layout = nullptr;  // null: no row matches
};

// The container, read, and its layout. Errors: the file cannot be read or
// is not a container we read ("not a zip archive", a pickle error, ...).
Result<MotionFile> readMotionFile(const std::string& path);

// The same, except that an .npz is not decoded at all (member names only):
// enough to tell a motion from a shape file (batch mode).
Result<MotionFile> probeMotionFile(const std::string& path);

}  // namespace smpl
