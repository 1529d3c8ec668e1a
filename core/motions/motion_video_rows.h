// Per-person rows as video-to-motion tools store them (WHAM, VIBE, PHALP,
// GVHMR, TRAM, ROMP/BEV, EasyMocap; docs/motions.md "Video-to-motion
// layouts"): the readers' shared steps from a tree node to Motion fields.
// Every function names `context` ("wham_output.pkl: track 1") and the key in
// its errors, e.g. "wham_output.pkl: track 1: 'pose' has shape (25,70);
// expected (25,72) SMPL axis-angle".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {
namespace video_rows {

// An Array leaf, or a List of equal-shaped numeric leaves stacked into one
// (per-detection lists such as ROMP's `smpl_thetas`, PHALP's `camera`).
struct Rows {
  const Array* leaf = nullptr;  // the node's own leaf, when it is one
  Array stacked;                // otherwise the stacked list
  const Array& get() const { return leaf ? *leaf : stacked; }
};

// `node` (the child `key` of a track's dict) as Rows. Errors: missing
// ("missing key 'pose'"), not an array or a list of arrays, text.
Status rowsOf(const DataNode* node, const std::string& context, const char* key, Rows* out);

// The number of elements of a per-detection list: a List's children, or the
// first dimension of an Array leaf (0 for None).
size_t countOf(const DataNode* node);

// Element `i` of a per-detection list (a List child, or row i of an Array
// leaf copied into `scratch`, charged to the memory budget first); nullptr
// when out of range or not numeric. Error: the budget, naming `context`.
Result<const Array*> elementOf(const DataNode* node, size_t i, const std::string& context,
                               Array* scratch);

// The child `key` of a track's dict as per-frame betas rows (T,B), T =
// m->frames.size(): their mean into m->betas (putBetas, the note prefixed
// "track <id>: "). Absent: nothing. Errors: a shape other than (T,B).
Status putTrackBetas(const DataNode& track, const char* key, const std::string& context, Motion* m);

// T frames of SMPL (24 joints) rotations from (T,72) or (T,24,3) axis-angle
// or (T,24,3,3) row-major matrices into m->frames (allocated here, charged;
// m->layout = SMPL) and T zero translations. T >= 1.
Status putSmplPoses(const Array& a, const std::string& context, const char* key, Motion* m);

// (T,3) or (T,1,3) metres into m->translation, T = m->frames.size().
Status putTranslation(const Array& a, const std::string& context, const char* key, Motion* m);

// Per-detection betas rows (T,B) (or one row): their mean (core/models/betas_rows.h),
// with the note "<note_prefix>betas: ... using their mean" when rows differ.
Status putBetas(const Array& a, const std::string& context, const char* key,
                const std::string& note_prefix, Motion* m);

// `t` source frame numbers from an integer array of t elements (WHAM
// `frame_ids`, TRAM `frame`, ROMP `frame_id`): non-negative integers.
Result<std::vector<int64_t>> frameIds(const Array& a, size_t t, const std::string& context,
                                      const char* key);

// A track id as decimal text from a one-element integer array (PHALP `tid`
// entries, EasyMocap `id`); error when it is not a non-negative integer, and
// for 9e15 and above (array values are doubles: neighbouring integers there
// would share an id), an error that says so instead of a rounded id.
Result<std::string> idText(double value, const std::string& context, const char* key);

}  // namespace video_rows
}  // namespace smpl
