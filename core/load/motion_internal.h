// Shared by the motion readers (motion.cpp, motion_smplcodec.cpp,
// motion_fit.cpp, motion_aist.cpp); not part of the public API.
#pragma once

#include <string>

#include "core/array.h"
#include "core/load/motion.h"
#include "core/result.h"

namespace smpl {
namespace motion_detail {

// Which reader a file's keys call for (first match wins):
//   SmplCodec  `bodyPose` (Meshcapade .smpl)
//   Aist       `smpl_poses` (AIST++)
//   Poses      `poses` or `root_orient` (AMASS and plain files)
//   Fit        `body_pose` or `global_orient` (SMPLify-X / PIXIE / ExPose style)
//   NoPoses    none of these (AMASS shape.npz, *_stagei.npz, shape-only .smpl)
// A .smpl with `smplVersion` but no `bodyPose` (no frameCount) is a body
// shape only: NoPoses.
enum class Format { Poses, SmplCodec, Fit, Aist, NoPoses };
Format detectFormat(const ArrayDict& arrays);

const Array* find(const ArrayDict& d, const char* key);

// T frames of `joints` rest rotations, charged to m->charge (the memory budget).
Status allocateFrames(int64_t t, size_t joints, const std::string& path, Motion* m);

// Numbers (not text), all finite; else "<path>: '<key>' ..." errors.
Status checkNumbers(const Array& a, const std::string& path, const char* key);

// `count` consecutive axis-angle triples or row-major 3x3 matrices from `p`
// into out[first..first+count).
void putAxisAngle(const double* p, int count, int first, Rotations* out);
void putMatrices(const double* p, int count, int first, Rotations* out);

}  // namespace motion_detail
}  // namespace smpl
