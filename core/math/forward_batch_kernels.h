// The two inner loops of forwardBatch (core/math/forward_batch.h), written
// out for the CPU: an AVX2+FMA version, chosen at run time when the CPU has
// it (cpuid), and a portable version with the same arithmetic order per
// element class (tests run both). No Eigen inside the AVX2 functions, so no
// template compiled for AVX2 can be merged into code run on older CPUs.
//
// Cost per frame for the 6890-vertex, 207-feature SMPL layout: the
// corrective product is 3N*P = 4.3 M multiply-adds, the skinning N*K*12 =
// 2.0 M (dense weights); the rest (kinematic chain, pose features) is O(K).
#pragma once

#include <cstddef>
#include <vector>

namespace smpl {
namespace batch {

// True if the AVX2+FMA kernels run on this CPU.
bool haveAvx2Fma();

// posedirs (3N x P, column-major doubles) as float panels of kPanelRows rows:
// panel q holds rows [16q, 16q+16) for every feature p at
// data[(q * depth + p) * 16 + r]; rows past 3N are zero.
constexpr int kPanelRows = 16;
struct PackedPosedirs {
  std::vector<float> data;
  int rows = 0;         // 3N
  int rows_padded = 0;  // rows rounded up to kPanelRows
  int depth = 0;        // P
};
PackedPosedirs packPosedirs(const double* posedirs, int rows, int depth);

// out = posedirs * features: features is P x cols (column-major floats, pose
// features f of each frame); out is rows_padded x cols, column-major.
void correctiveProduct(const PackedPosedirs& a, const float* features, int cols, float* out,
                       bool simd);

// One frame's linear blend skinning. weights: N x K column-major floats;
// transforms: K x 12 row-major floats (top 3x4 rows of G_k [I | -J_k], row
// by row); v_shaped: N x 3 column-major doubles; correctives: 3N floats
// (x0 y0 z0 x1 ...); out: 3N doubles (x0 y0 z0 ...), metres.
// out_i = (sum_k w_ik T_k) [v_shaped_i + c_i; 1].
void skinFrame(const float* weights, int n, int k, const float* transforms, const double* v_shaped,
               const float* correctives, double* out, bool simd);

}  // namespace batch
}  // namespace smpl
