// The motion reader table: one row per motion layout (a tool's way of
// writing poses: AMASS, SMPLCodec, fits, AIST++, ...). loadMotion
// (motion.h) reads a file's container, asks each row in order whether the
// file's keys are its layout, reads only that row's keys (an .npz is lazy:
// nothing else is decoded) and calls the row's decode function. The "no pose
// data" and "unknown layout" messages, batch mode's motion extensions and the
// key list of the lazy .npz all come from this table.
//
// Adding a layout is one file and one row (docs/architecture.md "Add a motion
// layout"): core/motions/motion_<name>.{h,cpp} defines `matches` and `decode`
// and returns its row from a function; core/motions/motion_layouts.cpp lists it.
// Rows are tried in table order; put a row whose keys are a subset of another
// layout's after that layout.
#pragma once

#include <string>
#include <vector>

#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

// The containers a motion file can come in (by content, not by extension),
// as a bit set; and the file name extensions batch mode lists for each.
enum ContainerBits : unsigned {
  kNpzFile = 1u << 0,     // .npz / .smpl (zip of .npy members)
  kPickleFile = 1u << 1,  // .pkl (the data-only unpickler)
  kJsonFile = 1u << 2,    // .json
  kJoblibFile = 1u << 3,  // joblib.dump, plain or zlib/gzip (.pkl, .joblib)
  kTorchFile = 1u << 4,   // torch.save's zip (.pt, .pth)
  kNpyFile = 1u << 5,     // np.save: an array or an object (.npy)
};
constexpr unsigned kAnyContainer =
    kNpzFile | kPickleFile | kJsonFile | kJoblibFile | kTorchFile | kNpyFile;

// What a decode function gets besides the file's data.
struct LayoutInput {
  std::string path;  // names the file in errors
  MotionOptions options;
};

struct MotionLayout {
  const char* name;       // short name: "amass", "smplcodec", ... (docs/motions.md's rows)
  const char* describes;  // for messages: "AMASS or plain poses (T,3J)"
  unsigned containers;    // ContainerBits it can come in
  // True when `root` (a Dict; for an .npz its members' names only, each a
  // None node) is this layout's. Decides by keys, never by values.
  bool (*matches)(const DataNode& root);
  // The top-level keys decode reads; an .npz decodes only these members.
  std::vector<std::string> keys;
  // `root` holds the decoded keys. Fills tracks (at least one on success);
  // fps 0 when the file stores no rate (loadMotion then settles it:
  // --source-fps, else fps_fallback with a note). Errors: one line naming
  // in.path and the key. A decode may set Motion::source_layout to a variant's
  // name (the ROMP row's BEV files), else the row's name is used.
  Status (*decode)(const DataNode& root, const LayoutInput& in, MotionSet* out);
  double fps_fallback = 30.0;                       // rate assumed when the file stores none
  const char* fps_why = "no frame rate is stored";  // the note's reason, with fps_fallback
};

// Every layout, in detection order.
const std::vector<MotionLayout>& motionLayouts();

// The first row whose `matches` accepts `root` and whose containers include
// `container` (a ContainerBits value), or nullptr.
const MotionLayout* findLayout(const DataNode& root, unsigned container);

// The extensions batch mode lists as motions (".npz", ".smpl", ".pkl", ".json"):
// those of the containers of every row. Our own sidecars (*.smpl.json) are
// excluded by batch mode.
std::vector<std::string> motionFileExtensions();

// The message for a file no row matches: "a body model file (keys ...), not
// a motion: give it as --model ..." for a model's arrays (v_template with
// shapedirs, posedirs, weights or J_regressor), "no pose data (keys betas,
// gender): a shape file, not a motion: give it as --betas-file" when no key
// looks like pose data, else "keys found: a, b, ...; supported layouts: motions.md in <docs
// folder>" (keys sorted, at most 12, through printable(); core/docs_location.h says which folder,
// or names the documentation in general).
std::string unmatchedMessage(const DataNode& root);

// True for a Dict with a betas key (betas, shape, shapeParameters) and no key
// that looks like pose data (batch mode skips such files with a note
// instead of failing them); a file without betas is never called a shape file.
bool isShapeOnly(const DataNode& root);

// True for a Dict holding a body model's arrays: v_template and at least one
// of shapedirs, posedirs, weights, J_regressor.
bool isBodyModel(const DataNode& root);

}  // namespace smpl
