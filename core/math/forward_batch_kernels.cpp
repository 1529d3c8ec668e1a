// Kernels of forwardBatch (forward_batch_kernels.h): packing, the per-step
// GEMM and skinning of each kernel set, and evaluateBlock, which runs a
// block of frames step by step (32 vertices at a time) so the step's
// correctives go from the GEMM to the skinning through L1/L2, not memory.
#include "core/math/forward_batch_kernels.h"

// GCC 12's _mm512_undefined_pd (inside _mm512_cvtps_pd) reads itself on
// purpose; -Wmaybe-uninitialized reports it at every use.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace smpl {
namespace batch {
namespace {

constexpr int kL = kBlockVertices;  // 16

// Plain functions, not std::min/max templates, inside the target functions.
inline int imin(int a, int b) { return a < b ? a : b; }
inline int clampLanes(int count) { return count < 0 ? 0 : count > 8 ? 8 : count; }
inline unsigned char laneMask(int lanes) {  // the low `lanes` (0..8) bits
  return static_cast<unsigned char>((1u << clampLanes(lanes)) - 1);
}

// ---------------------------------------------------------------- AVX-512

// One 48 x 8 tile: corr rows [0, 48) of 8 frames (stride kStepRows) =
// panels a, a + ps, a + 2 ps (16 x depth each, feature-major) times b
// (depth x 8, interleaved by frame: b[8 p + j]). 24 named accumulators (GCC
// keeps an array of vectors in memory); the broadcasts fold into the FMAs.
__attribute__((target("avx512f,fma"), always_inline)) inline void tile48x8(const float* a,
                                                                          size_t ps,
                                                                          const float* b, int depth,
                                                                          float* corr) {
  __m512 c00 = _mm512_setzero_ps(), c01 = c00, c02 = c00, c10 = c00, c11 = c00, c12 = c00,
         c20 = c00, c21 = c00, c22 = c00, c30 = c00, c31 = c00, c32 = c00, c40 = c00, c41 = c00,
         c42 = c00, c50 = c00, c51 = c00, c52 = c00, c60 = c00, c61 = c00, c62 = c00, c70 = c00,
         c71 = c00, c72 = c00;
  const float *a0 = a, *a1 = a + ps, *a2 = a + 2 * ps;
  for (int p = 0; p < depth; ++p, a0 += kL, a1 += kL, a2 += kL, b += 8) {
    const __m512 x0 = _mm512_loadu_ps(a0), x1 = _mm512_loadu_ps(a1), x2 = _mm512_loadu_ps(a2);
    __m512 s = _mm512_set1_ps(b[0]);
    c00 = _mm512_fmadd_ps(x0, s, c00), c01 = _mm512_fmadd_ps(x1, s, c01);
    c02 = _mm512_fmadd_ps(x2, s, c02);
    s = _mm512_set1_ps(b[1]);
    c10 = _mm512_fmadd_ps(x0, s, c10), c11 = _mm512_fmadd_ps(x1, s, c11);
    c12 = _mm512_fmadd_ps(x2, s, c12);
    s = _mm512_set1_ps(b[2]);
    c20 = _mm512_fmadd_ps(x0, s, c20), c21 = _mm512_fmadd_ps(x1, s, c21);
    c22 = _mm512_fmadd_ps(x2, s, c22);
    s = _mm512_set1_ps(b[3]);
    c30 = _mm512_fmadd_ps(x0, s, c30), c31 = _mm512_fmadd_ps(x1, s, c31);
    c32 = _mm512_fmadd_ps(x2, s, c32);
    s = _mm512_set1_ps(b[4]);
    c40 = _mm512_fmadd_ps(x0, s, c40), c41 = _mm512_fmadd_ps(x1, s, c41);
    c42 = _mm512_fmadd_ps(x2, s, c42);
    s = _mm512_set1_ps(b[5]);
    c50 = _mm512_fmadd_ps(x0, s, c50), c51 = _mm512_fmadd_ps(x1, s, c51);
    c52 = _mm512_fmadd_ps(x2, s, c52);
    s = _mm512_set1_ps(b[6]);
    c60 = _mm512_fmadd_ps(x0, s, c60), c61 = _mm512_fmadd_ps(x1, s, c61);
    c62 = _mm512_fmadd_ps(x2, s, c62);
    s = _mm512_set1_ps(b[7]);
    c70 = _mm512_fmadd_ps(x0, s, c70), c71 = _mm512_fmadd_ps(x1, s, c71);
    c72 = _mm512_fmadd_ps(x2, s, c72);
  }
  const __m512 all[8][3] = {{c00, c01, c02}, {c10, c11, c12}, {c20, c21, c22}, {c30, c31, c32},
                            {c40, c41, c42}, {c50, c51, c52}, {c60, c61, c62}, {c70, c71, c72}};
  for (int j = 0; j < 8; ++j)
    for (int d = 0; d < 3; ++d) _mm512_storeu_ps(corr + j * kStepRows + d * kL, all[j][d]);
}

// The step's correctives: corr[t * 96 + r] for every frame t of `tiles`
// tiles of 8 (b: tile after tile, depth x 8 each), r = 48 h + 16 d + lane.
__attribute__((target("avx512f,fma"))) void gemmAvx512(const float* a, int depth, const float* b,
                                                       int tiles, float* corr) {
  const size_t ps = static_cast<size_t>(depth) * kL;
  for (int t = 0; t < tiles; ++t)  // the tile's features (6.6 KB) in L1, the panels from L2
    for (int h = 0; h < 2; ++h)
      tile48x8(a + 3 * h * ps, ps, b + static_cast<size_t>(t) * depth * 8, depth,
               corr + static_cast<size_t>(t) * 8 * kStepRows + 3 * kL * h);
}

// Writes 8 vertices' x y z (doubles X, Y, Z) interleaved at dst, the first
// `count` of them (0..8).
__attribute__((target("avx512f,fma"), always_inline)) inline void storeXyz(__m512d x, __m512d y,
                                                                          __m512d z, double* dst,
                                                                          int count) {
  // Output element e = 8 m + k holds component e % 3 of vertex e / 3.
  const __m512i xy0 = _mm512_set_epi64(10, 2, 0, 9, 1, 0, 8, 0),
                xyz0 = _mm512_set_epi64(7, 6, 9, 4, 3, 8, 1, 0);
  const __m512i xy1 = _mm512_set_epi64(5, 0, 12, 4, 0, 11, 3, 0),
                xyz1 = _mm512_set_epi64(7, 12, 5, 4, 11, 2, 1, 10);
  const __m512i xy2 = _mm512_set_epi64(0, 15, 7, 0, 14, 6, 0, 13),
                xyz2 = _mm512_set_epi64(15, 6, 5, 14, 3, 2, 13, 0);
  const __m512d o0 = _mm512_permutex2var_pd(_mm512_permutex2var_pd(x, xy0, y), xyz0, z);
  const __m512d o1 = _mm512_permutex2var_pd(_mm512_permutex2var_pd(x, xy1, y), xyz1, z);
  const __m512d o2 = _mm512_permutex2var_pd(_mm512_permutex2var_pd(x, xy2, y), xyz2, z);
  if (count == 8) {
    _mm512_storeu_pd(dst, o0), _mm512_storeu_pd(dst + 8, o1), _mm512_storeu_pd(dst + 16, o2);
    return;
  }
  const int values = 3 * count;  // 0..21
  _mm512_mask_storeu_pd(dst, laneMask(values), o0);
  _mm512_mask_storeu_pd(dst + 8, laneMask(values - 8), o1);
  _mm512_mask_storeu_pd(dst + 16, laneMask(values - 16), o2);
}

// Copies the first `count` doubles of a step's frame result from the
// staging buffer to dst past the caches: stage + off mirrors dst's
// alignment (off = (dst mod 64) / 8), so every cache line of dst that the
// result covers whole gets one aligned non-temporal store; the partial lines
// at the ends (shared with the neighbouring steps) get masked plain stores.
__attribute__((target("avx512f,fma"), always_inline)) inline void streamOut(const double* stage,
                                                                           int off, int count,
                                                                           double* dst) {
  const uintptr_t base = reinterpret_cast<uintptr_t>(dst) - 8 * static_cast<uintptr_t>(off);
  for (int line = 0; 8 * line - off < count; ++line) {
    const int k0 = 8 * line - off;  // dst index of the line's first double
    const __m512d v = _mm512_load_pd(stage + 8 * line);
    double* d = reinterpret_cast<double*>(base + 64 * static_cast<uintptr_t>(line));
    if (k0 >= 0 && k0 + 8 <= count) {
      _mm512_stream_pd(d, v);
    } else {
      const int lo = k0 < 0 ? -k0 : 0, hi = count - k0 < 8 ? count - k0 : 8;
      _mm512_mask_storeu_pd(d, static_cast<__mmask8>(laneMask(hi) & ~laneMask(lo)), v);
    }
  }
}

// One step's skinning, every frame. joints/w: the step's joint list and
// its 32 weights per entry; rest: the step's packed rest positions (96
// doubles); corr: the step's correctives (96 per frame); out + t*ld: frame
// t's 3N doubles.
__attribute__((target("avx512f,fma"))) void skinAvx512(const int* joints, int count,
                                                       const float* w, int first, int n,
                                                       const double* rest, const float* corr,
                                                       int frames, const float* transforms, int k,
                                                       double* out, size_t ld, bool stream) {
  const int valid = imin(kStepVertices, n - first);
  alignas(64) float blended[12][kStepVertices];
  alignas(64) double stage[kStepRows + 16];
  for (int t = 0; t < frames; ++t) {
    const float* tr = transforms + static_cast<size_t>(t) * k * 12;
    __m512 m00 = _mm512_setzero_ps(), m01 = m00, m10 = m00, m11 = m00, m20 = m00, m21 = m00,
           m30 = m00, m31 = m00, m40 = m00, m41 = m00, m50 = m00, m51 = m00, m60 = m00,
           m61 = m00, m70 = m00, m71 = m00, m80 = m00, m81 = m00, m90 = m00, m91 = m00,
           ma0 = m00, ma1 = m00, mb0 = m00, mb1 = m00;
    for (int e = 0; e < count; ++e) {
      const __m512 w0 = _mm512_load_ps(w + 32 * e), w1 = _mm512_load_ps(w + 32 * e + 16);
      const float* tj = tr + joints[e] * 12;
      __m512 s = _mm512_set1_ps(tj[0]);
      m00 = _mm512_fmadd_ps(w0, s, m00), m01 = _mm512_fmadd_ps(w1, s, m01);
      s = _mm512_set1_ps(tj[1]);
      m10 = _mm512_fmadd_ps(w0, s, m10), m11 = _mm512_fmadd_ps(w1, s, m11);
      s = _mm512_set1_ps(tj[2]);
      m20 = _mm512_fmadd_ps(w0, s, m20), m21 = _mm512_fmadd_ps(w1, s, m21);
      s = _mm512_set1_ps(tj[3]);
      m30 = _mm512_fmadd_ps(w0, s, m30), m31 = _mm512_fmadd_ps(w1, s, m31);
      s = _mm512_set1_ps(tj[4]);
      m40 = _mm512_fmadd_ps(w0, s, m40), m41 = _mm512_fmadd_ps(w1, s, m41);
      s = _mm512_set1_ps(tj[5]);
      m50 = _mm512_fmadd_ps(w0, s, m50), m51 = _mm512_fmadd_ps(w1, s, m51);
      s = _mm512_set1_ps(tj[6]);
      m60 = _mm512_fmadd_ps(w0, s, m60), m61 = _mm512_fmadd_ps(w1, s, m61);
      s = _mm512_set1_ps(tj[7]);
      m70 = _mm512_fmadd_ps(w0, s, m70), m71 = _mm512_fmadd_ps(w1, s, m71);
      s = _mm512_set1_ps(tj[8]);
      m80 = _mm512_fmadd_ps(w0, s, m80), m81 = _mm512_fmadd_ps(w1, s, m81);
      s = _mm512_set1_ps(tj[9]);
      m90 = _mm512_fmadd_ps(w0, s, m90), m91 = _mm512_fmadd_ps(w1, s, m91);
      s = _mm512_set1_ps(tj[10]);
      ma0 = _mm512_fmadd_ps(w0, s, ma0), ma1 = _mm512_fmadd_ps(w1, s, ma1);
      s = _mm512_set1_ps(tj[11]);
      mb0 = _mm512_fmadd_ps(w0, s, mb0), mb1 = _mm512_fmadd_ps(w1, s, mb1);
    }
    const __m512 all[12][2] = {{m00, m01}, {m10, m11}, {m20, m21}, {m30, m31},
                               {m40, m41}, {m50, m51}, {m60, m61}, {m70, m71},
                               {m80, m81}, {m90, m91}, {ma0, ma1}, {mb0, mb1}};
    for (int e = 0; e < 12; ++e) {
      _mm512_store_ps(blended[e], all[e][0]);
      _mm512_store_ps(blended[e] + 16, all[e][1]);
    }
    // In double, 8 vertices at a time: p = rest + c, out = M [p; 1].
    const float* c = corr + static_cast<size_t>(t) * kStepRows;
    double* dst = out + static_cast<size_t>(t) * ld + 3 * static_cast<size_t>(first);
    const int off = static_cast<int>(reinterpret_cast<uintptr_t>(dst) & 63) / 8;
    double* target = stream ? stage + off : dst;
    for (int g = 0; g < 4 && 8 * g < valid; ++g) {
      const int lane = 8 * g;  // first lane in the step; block g / 2
      const float* ch = c + 3 * kL * (g / 2) + 8 * (g % 2);
      const __m512d px =
          _mm512_add_pd(_mm512_load_pd(rest + lane), _mm512_cvtps_pd(_mm256_loadu_ps(ch)));
      const __m512d py = _mm512_add_pd(_mm512_load_pd(rest + kStepVertices + lane),
                                       _mm512_cvtps_pd(_mm256_loadu_ps(ch + kL)));
      const __m512d pz = _mm512_add_pd(_mm512_load_pd(rest + 2 * kStepVertices + lane),
                                       _mm512_cvtps_pd(_mm256_loadu_ps(ch + 2 * kL)));
      __m512d r[3];
      for (int row = 0; row < 3; ++row) {
        const float* mr = &blended[4 * row][lane];
        __m512d acc = _mm512_cvtps_pd(_mm256_load_ps(mr + 3 * kStepVertices));
        acc = _mm512_fmadd_pd(_mm512_cvtps_pd(_mm256_load_ps(mr)), px, acc);
        acc = _mm512_fmadd_pd(_mm512_cvtps_pd(_mm256_load_ps(mr + kStepVertices)), py, acc);
        r[row] = _mm512_fmadd_pd(_mm512_cvtps_pd(_mm256_load_ps(mr + 2 * kStepVertices)), pz, acc);
      }
      storeXyz(r[0], r[1], r[2], target + 3 * lane, stream ? 8 : imin(8, valid - lane));
    }
    if (stream) streamOut(stage, off, 3 * valid, dst);
  }
  if (stream) _mm_sfence();  // the streamed lines are visible before the caller goes on
}

// ---------------------------------------------------------------- AVX2

// One 16 x 6 tile: corr rows [0, 16) of 6 frames (stride kStepRows) =
// panel (16 x depth) * b (depth x 6, b[6 p + j]). Twelve named accumulators.
__attribute__((target("avx2,fma"), always_inline)) inline void tile16x6(const float* panel,
                                                                       const float* b, int depth,
                                                                       float* corr) {
  __m256 c00 = _mm256_setzero_ps(), c01 = c00, c10 = c00, c11 = c00, c20 = c00, c21 = c00,
         c30 = c00, c31 = c00, c40 = c00, c41 = c00, c50 = c00, c51 = c00;
  for (int p = 0; p < depth; ++p, panel += kL, b += 6) {
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
  const __m256 lo[6] = {c00, c10, c20, c30, c40, c50}, hi[6] = {c01, c11, c21, c31, c41, c51};
  for (int j = 0; j < 6; ++j) {
    _mm256_storeu_ps(corr + j * kStepRows, lo[j]);
    _mm256_storeu_ps(corr + j * kStepRows + 8, hi[j]);
  }
}

__attribute__((target("avx2,fma"))) void gemmAvx2(const float* a, int depth, const float* b,
                                                  int tiles, float* corr) {
  const size_t ps = static_cast<size_t>(depth) * kL;
  for (int q = 0; q < 6; ++q)  // panel q: rows 16 q of the step
    for (int t = 0; t < tiles; ++t)
      tile16x6(a + q * ps, b + static_cast<size_t>(t) * depth * 6, depth,
               corr + static_cast<size_t>(t) * 6 * kStepRows + kL * q);
}

// out = m [x y z 1] for one vertex, m the blended 3x4 transform (float,
// entry e at m[e * stride]), the position and the result in double.
inline void transformVertex(const float* m, size_t stride, double x, double y, double z,
                            double* dst) {
  for (int r = 0; r < 3; ++r)
    dst[r] = m[4 * r * stride] * x + m[(4 * r + 1) * stride] * y + m[(4 * r + 2) * stride] * z +
             m[(4 * r + 3) * stride];
}

// 8 vertices per step of the loop, 12 blended entries in 12 named
// registers; the transform one vertex at a time.
__attribute__((target("avx2,fma"))) void skinAvx2(const int* joints, int count, const float* w,
                                                  int first, int n, const double* rest,
                                                  const float* corr, int frames,
                                                  const float* transforms, int k, double* out,
                                                  size_t ld, bool) {
  const int valid = imin(kStepVertices, n - first);
  alignas(32) float m[12][8];
  for (int t = 0; t < frames; ++t) {
    const float* tr = transforms + static_cast<size_t>(t) * k * 12;
    const float* c = corr + static_cast<size_t>(t) * kStepRows;
    double* dst = out + static_cast<size_t>(t) * ld;
    for (int g = 0; g < 4 && 8 * g < valid; ++g) {
      __m256 m0 = _mm256_setzero_ps(), m1 = m0, m2 = m0, m3 = m0, m4 = m0, m5 = m0, m6 = m0,
             m7 = m0, m8 = m0, m9 = m0, m10 = m0, m11 = m0;
      for (int e = 0; e < count; ++e) {
        const __m256 wj = _mm256_load_ps(w + 32 * e + 8 * g);
        const float* tj = tr + joints[e] * 12;
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
      const float* cg = c + 3 * kL * (g / 2) + 8 * (g % 2);
      for (int l = 0; l < 8 && 8 * g + l < valid; ++l) {
        const int lane = 8 * g + l;
        transformVertex(&m[0][l], 8, rest[lane] + cg[l], rest[kStepVertices + lane] + cg[kL + l],
                        rest[2 * kStepVertices + lane] + cg[2 * kL + l],
                        dst + 3 * (first + lane));
      }
    }
  }
}

// ---------------------------------------------------------------- portable

// b is one tile of all `cols` frames (b[cols * p + j]).
void gemmPortable(const float* a, int depth, const float* b, int cols, float* corr) {
  const size_t ps = static_cast<size_t>(depth) * kL;
  const Eigen::Map<const Eigen::MatrixXf> ft(b, cols, depth);  // frames x features
  for (int q = 0; q < 6; ++q) {
    Eigen::Map<Eigen::MatrixXf, 0, Eigen::OuterStride<>> c(corr + kL * q, kL, cols,
                                                           Eigen::OuterStride<>(kStepRows));
    c.noalias() = Eigen::Map<const Eigen::MatrixXf>(a + q * ps, kL, depth) * ft.transpose();
  }
}

void skinPortable(const int* joints, int count, const float* w, int first, int n,
                  const double* rest, const float* corr, int frames, const float* transforms,
                  int k, double* out, size_t ld, bool) {
  const int valid = std::min(kStepVertices, n - first);
  for (int t = 0; t < frames; ++t) {
    const float* tr = transforms + static_cast<size_t>(t) * k * 12;
    const float* c = corr + static_cast<size_t>(t) * kStepRows;
    for (int l = 0; l < valid; ++l) {
      float m[12] = {};
      for (int e = 0; e < count; ++e) {
        const float wl = w[32 * e + l];
        if (wl == 0.0f) continue;
        const float* tj = tr + joints[e] * 12;
        for (int q = 0; q < 12; ++q) m[q] += wl * tj[q];
      }
      const float* cl = c + 3 * kL * (l / kL) + l % kL;
      transformVertex(m, 1, rest[l] + cl[0], rest[kStepVertices + l] + cl[kL],
                      rest[2 * kStepVertices + l] + cl[2 * kL],
                      out + static_cast<size_t>(t) * ld + 3 * (first + l));
    }
  }
}

// ---------------------------------------------------------------- dispatch

using GemmFn = void (*)(const float*, int, const float*, int, float*);
using SkinFn = void (*)(const int*, int, const float*, int, int, const double*, const float*, int,
                        const float*, int, double*, size_t, bool);
struct KernelSet {
  GemmFn gemm;
  SkinFn skin;
  int tile_cols;  // frames per GEMM tile; 0: one tile of the whole block
};

KernelSet kernelSet(Kernels kernels) {
  switch (kernels) {
    case Kernels::Avx512:
      return {&gemmAvx512, &skinAvx512, 8};
    case Kernels::Avx2:
      return {&gemmAvx2, &skinAvx2, 6};
    default:
      return {&gemmPortable, &skinPortable, 0};
  }
}

bool haveAvx2Fma() {
  static const bool have = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return have;
}

bool haveAvx512() {  // libgcc checks that the OS saves the zmm and mask state
  static const bool have = haveAvx2Fma() && __builtin_cpu_supports("avx512f");
  return have;
}

}  // namespace

bool cpuRuns(Kernels kernels) {
  switch (kernels) {
    case Kernels::Avx512:
      return haveAvx512();
    case Kernels::Avx2:
      return haveAvx2Fma();
    default:
      return true;
  }
}

Kernels resolveKernels(Kernels requested) {
  if (requested != Kernels::Best && cpuRuns(requested)) return requested;
  return haveAvx512() ? Kernels::Avx512 : haveAvx2Fma() ? Kernels::Avx2 : Kernels::Portable;
}

std::vector<Kernels> supportedKernels() {
  std::vector<Kernels> out;
  for (Kernels k : {Kernels::Portable, Kernels::Avx2, Kernels::Avx512})
    if (cpuRuns(k)) out.push_back(k);
  return out;
}

const char* kernelsName(Kernels kernels) {
  switch (kernels) {
    case Kernels::Best:
      return "best";
    case Kernels::Portable:
      return "portable";
    case Kernels::Avx2:
      return "avx2";
    case Kernels::Avx512:
      return "avx512";
  }
  return "?";
}

PackedPosedirs packPosedirs(const double* posedirs, int vertices, int depth) {
  PackedPosedirs a;
  a.vertices = vertices;
  a.depth = depth;
  a.steps = (vertices + kStepVertices - 1) / kStepVertices;
  const int blocks = 2 * a.steps;
  a.data.resize(static_cast<size_t>(blocks) * 3 * depth * kL);  // every element written below
  const size_t rows = 3 * static_cast<size_t>(vertices);
  // Feature by feature: each posedirs column is read in order, and each
  // destination write is one whole cache line (16 floats).
  for (int p = 0; p < depth; ++p) {
    const double* col = posedirs + p * rows;
    for (int b = 0; b < blocks; ++b) {
      const int lanes = std::max(0, std::min(kL, vertices - kL * b));
      const double* src = col + 3 * static_cast<size_t>(kL) * b;
      for (int d = 0; d < 3; ++d) {
        float* dst = a.data.data() + ((3 * static_cast<size_t>(b) + d) * depth + p) * kL;
        int l = 0;
        for (; l < lanes; ++l) dst[l] = static_cast<float>(src[3 * l + d]);
        for (; l < kL; ++l) dst[l] = 0.0f;
      }
    }
  }
  return a;
}

AlignedVector<double> packRest(const double* v_shaped, int vertices) {
  const int steps = (vertices + kStepVertices - 1) / kStepVertices;
  AlignedVector<double> rest(static_cast<size_t>(steps) * kStepRows);
  for (int s = 0; s < steps; ++s)
    for (int d = 0; d < 3; ++d)
      for (int l = 0; l < kStepVertices; ++l) {
        const int i = s * kStepVertices + l;
        rest[(3 * static_cast<size_t>(s) + d) * kStepVertices + l] =
            i < vertices ? v_shaped[static_cast<size_t>(d) * vertices + i] : 0.0;
      }
  return rest;
}

PackedSkin packSkin(const double* weights, int vertices, int joints) {
  PackedSkin s;
  const int steps = (vertices + kStepVertices - 1) / kStepVertices;
  s.begin.push_back(0);
  for (int st = 0; st < steps; ++st) {
    const int first = st * kStepVertices, valid = std::min(kStepVertices, vertices - first);
    for (int j = 0; j < joints; ++j) {
      const double* col = weights + static_cast<size_t>(j) * vertices + first;
      float w[kStepVertices] = {};
      int nonzero = 0;
      for (int l = 0; l < valid; ++l) nonzero += (w[l] = static_cast<float>(col[l])) != 0.0f;
      if (nonzero == 0) continue;
      s.nonzeros += nonzero;
      s.joints.push_back(j);
      s.w.insert(s.w.end(), w, w + kStepVertices);
    }
    s.begin.push_back(static_cast<int>(s.joints.size()));
  }
  return s;
}

void evaluateBlock(const PackedPosedirs& posedirs, const std::vector<const PackedSkin*>& skins,
                   const double* rest, const FrameBlock& block, double* const* out, size_t ld,
                   Kernels kernels, bool stream) {
  const KernelSet ks = kernelSet(kernels);
  const int depth = posedirs.depth, frames = block.frames, n = posedirs.vertices;
  const int width = ks.tile_cols > 0 ? ks.tile_cols : frames;
  const int tiles = (frames + width - 1) / width, cols = tiles * width;
  // Features tile by tile, interleaved by frame (b[width * p + j] within a
  // tile); the frames past the block are zero.
  AlignedVector<float> b(static_cast<size_t>(depth) * cols, 0.0f);
  for (int t = 0; t < frames; ++t) {
    float* tile = b.data() + static_cast<size_t>(t / width) * depth * width + t % width;
    const float* f = block.features + static_cast<size_t>(t) * depth;
    for (int p = 0; p < depth; ++p) tile[static_cast<size_t>(p) * width] = f[p];
  }
  AlignedVector<float> corr(static_cast<size_t>(kStepRows) * cols, 0.0f);
  for (int s = 0; s < posedirs.steps; ++s) {
    if (depth > 0)
      ks.gemm(posedirs.data.data() + static_cast<size_t>(s) * 6 * depth * kL, depth, b.data(),
              ks.tile_cols > 0 ? tiles : cols, corr.data());
    for (size_t i = 0; i < skins.size(); ++i) {
      const PackedSkin& sk = *skins[i];
      const int e0 = sk.begin[s];
      ks.skin(sk.joints.data() + e0, sk.begin[s + 1] - e0,
              sk.w.data() + static_cast<size_t>(e0) * kStepVertices, s * kStepVertices, n,
              rest + static_cast<size_t>(s) * kStepRows, corr.data(), frames, block.transforms,
              block.joints, out[i], ld, stream && kernels == Kernels::Avx512);
    }
  }
}

}  // namespace batch
}  // namespace smpl
