// Kernels of forwardBatch (forward_batch_kernels.h). The corrective product is
// a blocked GEMM: posedirs is packed once into 16-row float panels; a group of
// kGroupPanels panels (~200 KB, resident in L2) is multiplied by every frame of
// the block, 6 frames at a time, in a 16 x 6 register tile (12 AVX2
// accumulators, 2 loads and 6 broadcasts per 12 FMAs), so posedirs streams
// from memory once per block of frames instead of once per frame.
#include "core/math/forward_batch_kernels.h"

#include <immintrin.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstring>

namespace smpl {
namespace batch {
namespace {

constexpr int kTileCols = 6;      // frames per register tile
constexpr int kGroupPanels = 16;  // panels kept in L2 while the frames pass over them
constexpr int kSkinLanes = 8;     // vertices per AVX2 skinning step

// Features of frames [t0, t0 + nr) interleaved by feature, b[p * 6 + j];
// the columns past nr are zero (the tile always computes 6 frames).
void packFeatures(const float* features, int depth, int t0, int nr, float* b) {
  for (int p = 0; p < depth; ++p)
    for (int j = 0; j < kTileCols; ++j)
      b[p * kTileCols + j] = j < nr ? features[static_cast<size_t>(t0 + j) * depth + p] : 0.0f;
}

// One 16 x 6 tile: out(16 x nr, column stride ld) = panel (16 x depth) * b.
// Twelve named accumulators: GCC keeps an array of them in memory.
__attribute__((target("avx2,fma"))) void tileAvx2(const float* panel, const float* b, int depth,
                                                  float* out, size_t ld, int nr) {
  __m256 c00 = _mm256_setzero_ps(), c01 = c00, c10 = c00, c11 = c00, c20 = c00, c21 = c00,
         c30 = c00, c31 = c00, c40 = c00, c41 = c00, c50 = c00, c51 = c00;
  for (int p = 0; p < depth; ++p, panel += kPanelRows, b += kTileCols) {
    const __m256 a0 = _mm256_loadu_ps(panel), a1 = _mm256_loadu_ps(panel + 8);
    __m256 x = _mm256_broadcast_ss(b);
    c00 = _mm256_fmadd_ps(a0, x, c00), c01 = _mm256_fmadd_ps(a1, x, c01);
    x = _mm256_broadcast_ss(b + 1);
    c10 = _mm256_fmadd_ps(a0, x, c10), c11 = _mm256_fmadd_ps(a1, x, c11);
    x = _mm256_broadcast_ss(b + 2);
    c20 = _mm256_fmadd_ps(a0, x, c20), c21 = _mm256_fmadd_ps(a1, x, c21);
    x = _mm256_broadcast_ss(b + 3);
    c30 = _mm256_fmadd_ps(a0, x, c30), c31 = _mm256_fmadd_ps(a1, x, c31);
    x = _mm256_broadcast_ss(b + 4);
    c40 = _mm256_fmadd_ps(a0, x, c40), c41 = _mm256_fmadd_ps(a1, x, c41);
    x = _mm256_broadcast_ss(b + 5);
    c50 = _mm256_fmadd_ps(a0, x, c50), c51 = _mm256_fmadd_ps(a1, x, c51);
  }
  const __m256 lo[kTileCols] = {c00, c10, c20, c30, c40, c50},
               hi[kTileCols] = {c01, c11, c21, c31, c41, c51};
  for (int j = 0; j < nr; ++j) {
    _mm256_storeu_ps(out + j * ld, lo[j]);
    _mm256_storeu_ps(out + j * ld + 8, hi[j]);
  }
}

// The same tile with Eigen's (SSE2) product, for CPUs without AVX2.
void tilePortable(const float* panel, const float* b, int depth, float* out, size_t ld, int nr) {
  const Eigen::Map<const Eigen::MatrixXf> a(panel, kPanelRows, depth);
  const Eigen::Map<const Eigen::Matrix<float, kTileCols, Eigen::Dynamic>> f(b, kTileCols, depth);
  Eigen::Map<Eigen::MatrixXf, 0, Eigen::OuterStride<>> c(out, kPanelRows, nr,
                                                         Eigen::OuterStride<>(ld));
  c.noalias() = a * f.topRows(nr).transpose();
}

// out_i = m [x y z 1] for one vertex, m the blended 3x4 transform (float),
// the position and the result in double.
inline void transformVertex(const float* m, size_t stride, double x, double y, double z,
                            double* dst) {
  for (int r = 0; r < 3; ++r)
    dst[r] = m[4 * r * stride] * x + m[(4 * r + 1) * stride] * y + m[(4 * r + 2) * stride] * z +
             m[(4 * r + 3) * stride];
}

// Vertices [first, n) one at a time (the AVX2 path's tail).
void skinTail(const float* w, int n, int k, const float* t, const double* vs, const float* c,
              double* out, int first) {
  for (int i = first; i < n; ++i) {
    float m[12] = {};
    for (int j = 0; j < k; ++j) {
      const float wij = w[static_cast<size_t>(j) * n + i];
      if (wij == 0.0f) continue;
      for (int e = 0; e < 12; ++e) m[e] += wij * t[j * 12 + e];
    }
    transformVertex(m, 1, vs[i] + c[3 * i], vs[n + i] + c[3 * i + 1], vs[2 * n + i] + c[3 * i + 2],
                    out + 3 * i);
  }
}

// Portable: the blend as one Eigen product (N x K)(K x 12), then each vertex.
void skinPortable(const float* w, int n, int k, const float* t, const double* vs, const float* c,
                  double* out) {
  using Rows12 = Eigen::Matrix<float, Eigen::Dynamic, 12, Eigen::RowMajor>;
  Rows12 blended(n, 12);
  blended.noalias() =
      Eigen::Map<const Eigen::MatrixXf>(w, n, k) * Eigen::Map<const Rows12>(t, k, 12);
  for (int i = 0; i < n; ++i)
    transformVertex(blended.row(i).data(), 1, vs[i] + c[3 * i], vs[n + i] + c[3 * i + 1],
                    vs[2 * n + i] + c[3 * i + 2], out + 3 * i);
}

// 8 vertices per step: the 12 blended entries of 8 vertices in 12 registers
// (named: GCC keeps an array of vectors in memory), joints with no weight on
// any of the 8 skipped (real models have a few influences per vertex).
__attribute__((target("avx2,fma"))) void skinAvx2(const float* w, int n, int k, const float* t,
                                                  const double* vs, const float* c, double* out) {
  const int full = n - n % kSkinLanes;
  alignas(32) float m[12][kSkinLanes];
  for (int i0 = 0; i0 < full; i0 += kSkinLanes) {
    __m256 m0 = _mm256_setzero_ps(), m1 = m0, m2 = m0, m3 = m0, m4 = m0, m5 = m0, m6 = m0, m7 = m0,
           m8 = m0, m9 = m0, m10 = m0, m11 = m0;
    for (int j = 0; j < k; ++j) {
      const __m256 wj = _mm256_loadu_ps(w + static_cast<size_t>(j) * n + i0);
      if (_mm256_movemask_ps(_mm256_cmp_ps(wj, _mm256_setzero_ps(), _CMP_NEQ_UQ)) == 0)
        continue;  // no influence
      const float* tj = t + j * 12;
      m0 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 0), m0);
      m1 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 1), m1);
      m2 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 2), m2);
      m3 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 3), m3);
      m4 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 4), m4);
      m5 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 5), m5);
      m6 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 6), m6);
      m7 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 7), m7);
      m8 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 8), m8);
      m9 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 9), m9);
      m10 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 10), m10);
      m11 = _mm256_fmadd_ps(wj, _mm256_broadcast_ss(tj + 11), m11);
    }
    const __m256 all[12] = {m0, m1, m2, m3, m4, m5, m6, m7, m8, m9, m10, m11};
    for (int e = 0; e < 12; ++e) _mm256_store_ps(m[e], all[e]);
    for (int l = 0; l < kSkinLanes; ++l) {
      const int i = i0 + l;
      transformVertex(&m[0][l], kSkinLanes, vs[i] + c[3 * i], vs[n + i] + c[3 * i + 1],
                      vs[2 * n + i] + c[3 * i + 2], out + 3 * i);
    }
  }
  skinTail(w, n, k, t, vs, c, out, full);
}

}  // namespace

bool haveAvx2Fma() {
  static const bool have = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return have;
}

PackedPosedirs packPosedirs(const double* posedirs, int rows, int depth) {
  PackedPosedirs a;
  a.rows = rows;
  a.depth = depth;
  a.rows_padded = (rows + kPanelRows - 1) / kPanelRows * kPanelRows;
  a.data.assign(static_cast<size_t>(a.rows_padded) * depth, 0.0f);
  float* dst = a.data.data();
  for (int r0 = 0; r0 < rows; r0 += kPanelRows) {  // panel by panel: sequential writes
    const int height = std::min(kPanelRows, rows - r0);
    for (int p = 0; p < depth; ++p, dst += kPanelRows) {
      const double* src = posedirs + static_cast<size_t>(p) * rows + r0;
      for (int r = 0; r < height; ++r) dst[r] = static_cast<float>(src[r]);
    }
  }
  return a;
}

void correctiveProduct(const PackedPosedirs& a, const float* features, int cols, float* out,
                       bool simd) {
  const int depth = a.depth, panels = a.rows_padded / kPanelRows;
  const int tiles = (cols + kTileCols - 1) / kTileCols;
  std::vector<float> b(static_cast<size_t>(depth) * kTileCols *
                       tiles);  // frames packed tile by tile
  for (int t = 0; t < tiles; ++t)
    packFeatures(features, depth, t * kTileCols, std::min(kTileCols, cols - t * kTileCols),
                 b.data() + static_cast<size_t>(t) * depth * kTileCols);
  const size_t ld = a.rows_padded;
  const auto tile = simd ? &tileAvx2 : &tilePortable;
  for (int g = 0; g < panels; g += kGroupPanels) {
    const int group_end = std::min(panels, g + kGroupPanels);
    for (int t = 0; t < tiles; ++t) {
      const int t0 = t * kTileCols, nr = std::min(kTileCols, cols - t0);
      for (int q = g; q < group_end; ++q)
        tile(a.data.data() + static_cast<size_t>(q) * depth * kPanelRows,
             b.data() + static_cast<size_t>(t) * depth * kTileCols, depth,
             out + t0 * ld + static_cast<size_t>(q) * kPanelRows, ld, nr);
    }
  }
}

void skinFrame(const float* weights, int n, int k, const float* transforms, const double* v_shaped,
               const float* correctives, double* out, bool simd) {
  if (simd) return skinAvx2(weights, n, k, transforms, v_shaped, correctives, out);
  skinPortable(weights, n, k, transforms, v_shaped, correctives, out);
}

}  // namespace batch
}  // namespace smpl
