// Shared by the motion layouts (motion_amass.cpp, motion_smplcodec.cpp,
// motion_fit.cpp, motion_aist.cpp, ...); not part of the public API.
#pragma once

#include <string>
#include <utility>

#include "core/data_node.h"
#include "core/motions/motion.h"
#include "core/motions/motion_layout.h"
#include "core/result.h"

namespace smpl {
namespace motion_detail {

// The Array leaf `key` of a Dict node, or nullptr.
inline const Array* find(const DataNode& d, const char* key) { return d.leaf(key); }

// True when the Dict node has a child named `key` (any kind: for an .npz
// before decoding, members are None nodes).
inline bool has(const DataNode& d, const char* key) { return d.get(key) != nullptr; }

// T frames of `joints` rest rotations, charged to m->charge (the memory budget).
Status allocateFrames(int64_t t, size_t joints, const std::string& path, Motion* m);

// Numbers (not text), all finite; else "<path>: '<key>' ..." errors.
Status checkNumbers(const Array& a, const std::string& path, const char* key);

// Per-frame SMPL-X expression coefficients `key` into m->expression (T x E):
// (T,E), or one row (1,E) / (E,) for every frame; T = m->frames.size().
Status readExpression(const Array& a, const std::string& path, const char* key, Motion* m);

// `count` consecutive axis-angle triples or row-major 3x3 matrices from `p`
// into out[first..first+count).
void putAxisAngle(const double* p, int count, int first, Rotations* out);
void putMatrices(const double* p, int count, int first, Rotations* out);

// A layout's decode for files that hold one person: `Decode` fills one Motion.
template <Status (*Decode)(const DataNode&, const std::string&, Motion*)>
Status oneTrack(const DataNode& d, const LayoutInput& in, MotionSet* out) {
  Motion m;
  if (Status s = Decode(d, in.path, &m); !s) return s;
  out->tracks.push_back(std::move(m));
  return Status();
}

}  // namespace motion_detail
}  // namespace smpl
