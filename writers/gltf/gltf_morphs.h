// Internal to the glTF writer: one morph target's POSITION accessor in the
// encoding the options ask for.
//   dense float         the default: V x VEC3 FLOAT
//   sparse (epsilon>0)  vertices whose delta has |d| * peak <= epsilon (metres) are dropped; a
//                       sparse accessor (no bufferView: zeros) carries the rest,
//                       indices strictly increasing (vertex 0 kept if nothing
//                       else is). Where sparse would not be smaller than dense,
//                       the target is written dense with every delta kept.
//   quantized           values d (already divided by their peak, exporter/morph_scales.h)
//                       as normalised SHORT (KHR_mesh_quantization), q = round(32767 d);
//                       dense views use a stride of 8
// Bounds (min/max) are those of the decoded accessor, in the stored integer
// domain for SHORT, including the zeros a sparse accessor leaves.
#pragma once

#include <Eigen/Core>

#include "exporter/asset.h"
#include "writers/gltf/gltf_buffer.h"

namespace smpl {

struct MorphEncoding {
  double epsilon = 0.0;    // > 0: sparse; metres
  bool quantized = false;  // normalised SHORT (the deltas are already in [-1, 1])
  double peak = 1.0;       // metres per stored unit (MorphTarget::peak): the sparse
                           // test compares |d| * peak with epsilon
};

int addMorphTarget(GltfBuild& b, const MorphDeltas& deltas, const MorphEncoding& encoding);

}  // namespace smpl
