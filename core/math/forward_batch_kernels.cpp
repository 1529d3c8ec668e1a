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
// The AVX2 and AVX-512 kernels exist on x86-64 only (GCC and clang's target
// attributes); elsewhere (WebAssembly) the portable kernels are the only set.
#if defined(__x86_64__) && defined(__GNUC__)
#define SMPL_X86_KERNELS 1
#include <immintrin.h>
#else
#define SMPL_X86_KERNELS 0
#endif

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <cstring>

#include "core/huge_pages.h"
#include "core/parallel.h"

namespace smpl {
namespace batch {
namespace {

constexpr int kL = kBlockVertices;  // 16

// Plain functions, not std::min/max templates, inside the target functions.
[[maybe_unused]] inline int imin(int a, int b) { return a < b ? a : b; }
inline int clampLanes(int count) { return count < 0 ? 0 : count > 8 ? 8 : count; }
[[maybe_unused]] inline unsigned char laneMask(int lanes) {  // the low `lanes` (0..8) bits
  return static_cast<unsigned char>((1u << clampLanes(lanes)) - 1);
}

// What a skinning kernel gets for one step: the joints that weigh on the
// step and their 32 weights per entry, the step's rest positions and
// correctives (96 values per frame: block h, component d, lane l at
// 48 h + 16 d + l), and where each frame's 3N doubles go (out + t * ld).
struct SkinStep {
  const ptrdiff_t* joints;  // 12 * joint: where each entry's transform starts
  int count;                // entries in joints
  const float* w;           // count x 32
  int first, n;             // the step's first vertex; N
  const double* rest64;
  const float* rest32;
  const float* corr;  // frames x 96
  int frames;
  const float* transforms;  // frames x K x 12
  int k;
  double* out;
  size_t ld;
};

// out = m [x y z 1] for one vertex, m the blended 3x4 transform (float,
// entry e at m[e * stride]), the position and the result in double.
inline void transformVertex(const float* m, size_t stride, double x, double y, double z,
                            double* dst) {
  for (int r = 0; r < 3; ++r)
    dst[r] = m[4 * r * stride] * x + m[(4 * r + 1) * stride] * y + m[(4 * r + 2) * stride] * z +
             m[(4 * r + 3) * stride];
}

#if SMPL_X86_KERNELS
// ---------------------------------------------------------------- AVX-512

// One 48 x 8 tile: corr rows [0, 48) of 8 frames (stride kStepRows) =
// panels a, a + ps, a + 2 ps (16 x depth each, feature-major) times b
// (depth x 8, interleaved by frame: b[8 p + j]). 24 named accumulators (GCC
// keeps an array of vectors in memory). The loop runs 4 features at a time
// and on the way, per group of 4: prefetches 2 cache lines pf[...] into L2
// (the next step's panels, while this step's are in use) and, for writing,
// one result line pw[g] + pw_offset that the skinning of these frames will store (pw
// has an entry for every group: kernels' own scratch where there is none),
// so the result's memory traffic overlaps the multiply-adds instead of
// stalling the skinning's stores; pw entries past the groups come after.
#define SMPL_TILE48X8_FEATURE(o)                                                     \
  do {                                                                               \
    const __m512 x0 = _mm512_load_ps(a0 + (o)*kL), x1 = _mm512_load_ps(a1 + (o)*kL), \
                 x2 = _mm512_load_ps(a2 + (o)*kL);                                   \
    const float* bo = b + 8 * (o);                                                   \
    __m512 s = _mm512_set1_ps(bo[0]);                                                \
    c00 = _mm512_fmadd_ps(x0, s, c00), c01 = _mm512_fmadd_ps(x1, s, c01);            \
    c02 = _mm512_fmadd_ps(x2, s, c02);                                               \
    s = _mm512_set1_ps(bo[1]);                                                       \
    c10 = _mm512_fmadd_ps(x0, s, c10), c11 = _mm512_fmadd_ps(x1, s, c11);            \
    c12 = _mm512_fmadd_ps(x2, s, c12);                                               \
    s = _mm512_set1_ps(bo[2]);                                                       \
    c20 = _mm512_fmadd_ps(x0, s, c20), c21 = _mm512_fmadd_ps(x1, s, c21);            \
    c22 = _mm512_fmadd_ps(x2, s, c22);                                               \
    s = _mm512_set1_ps(bo[3]);                                                       \
    c30 = _mm512_fmadd_ps(x0, s, c30), c31 = _mm512_fmadd_ps(x1, s, c31);            \
    c32 = _mm512_fmadd_ps(x2, s, c32);                                               \
    s = _mm512_set1_ps(bo[4]);                                                       \
    c40 = _mm512_fmadd_ps(x0, s, c40), c41 = _mm512_fmadd_ps(x1, s, c41);            \
    c42 = _mm512_fmadd_ps(x2, s, c42);                                               \
    s = _mm512_set1_ps(bo[5]);                                                       \
    c50 = _mm512_fmadd_ps(x0, s, c50), c51 = _mm512_fmadd_ps(x1, s, c51);            \
    c52 = _mm512_fmadd_ps(x2, s, c52);                                               \
    s = _mm512_set1_ps(bo[6]);                                                       \
    c60 = _mm512_fmadd_ps(x0, s, c60), c61 = _mm512_fmadd_ps(x1, s, c61);            \
    c62 = _mm512_fmadd_ps(x2, s, c62);                                               \
    s = _mm512_set1_ps(bo[7]);                                                       \
    c70 = _mm512_fmadd_ps(x0, s, c70), c71 = _mm512_fmadd_ps(x1, s, c71);            \
    c72 = _mm512_fmadd_ps(x2, s, c72);                                               \
  } while (0)

__attribute__((target("avx512f,fma"), always_inline)) inline void tile48x8(
    const float* a, size_t ps, const float* b, int depth, float* corr, const char* pf,
    char* const* pw, int pw_lines, ptrdiff_t pw_offset) {
  __m512 c00 = _mm512_setzero_ps(), c01 = c00, c02 = c00, c10 = c00, c11 = c00, c12 = c00,
         c20 = c00, c21 = c00, c22 = c00, c30 = c00, c31 = c00, c32 = c00, c40 = c00, c41 = c00,
         c42 = c00, c50 = c00, c51 = c00, c52 = c00, c60 = c00, c61 = c00, c62 = c00, c70 = c00,
         c71 = c00, c72 = c00;
  const float *a0 = a, *a1 = a + ps, *a2 = a + 2 * ps;
  const int groups = depth / 4;
  for (int g = 0; g < groups; ++g, a0 += 4 * kL, a1 += 4 * kL, a2 += 4 * kL, b += 32) {
    _mm_prefetch(pf + 128 * g, _MM_HINT_T1);
    _mm_prefetch(pf + 128 * g + 64, _MM_HINT_T1);
    __builtin_prefetch(pw[g] + pw_offset, 1, 3);
    SMPL_TILE48X8_FEATURE(0);
    SMPL_TILE48X8_FEATURE(1);
    SMPL_TILE48X8_FEATURE(2);
    SMPL_TILE48X8_FEATURE(3);
  }
  for (int o = 0; o < depth - 4 * groups; ++o) SMPL_TILE48X8_FEATURE(o);
  const __m512 all[8][3] = {{c00, c01, c02}, {c10, c11, c12}, {c20, c21, c22}, {c30, c31, c32},
                            {c40, c41, c42}, {c50, c51, c52}, {c60, c61, c62}, {c70, c71, c72}};
  for (int j = 0; j < 8; ++j)
    for (int d = 0; d < 3; ++d) _mm512_store_ps(corr + j * kStepRows + d * kL, all[j][d]);
  for (int i = groups; i < pw_lines; ++i) __builtin_prefetch(pw[i] + pw_offset, 1, 3);
}
#undef SMPL_TILE48X8_FEATURE

// The step's correctives for `tiles` tiles of 8 frames: corr[t * 96 + r]
// for frame t (b: tile after tile, depth x 8 each), r = 48 h + 16 d + lane.
// Block by block (h), so a block's 3 panels (40 KB) stay in L1 while the
// tiles' features pass. On the way, a share of the pf_lines lines from pf
// (the next step's panels) and of the pw_lines result lines pw[] + pw_offset
// (padded with at least depth / 4 entries) per tile48x8.
__attribute__((target("avx512f,fma"))) void gemmAvx512(const float* a, int depth, const float* b,
                                                       int tiles, float* corr, const char* pf,
                                                       int pf_lines, char* const* pw, int pw_lines,
                                                       ptrdiff_t pw_offset) {
  const size_t ps = static_cast<size_t>(depth) * kL;
  const int calls = 2 * tiles;
  const int pf_share = (pf_lines + calls - 1) / calls, pw_share = (pw_lines + calls - 1) / calls;
  for (int h = 0, call = 0; h < 2; ++h)
    for (int t = 0; t < tiles; ++t, ++call) {
      const int w0 = imin(pw_lines, call * pw_share), f0 = imin(pf_lines, call * pf_share);
      tile48x8(a + 3 * h * ps, ps, b + static_cast<size_t>(t) * depth * 8, depth,
               corr + static_cast<size_t>(t) * 8 * kStepRows + 3 * kL * h,
               pf + 64 * static_cast<size_t>(f0), pw + w0, imin(pw_share, pw_lines - w0),
               pw_offset);
    }
}

// 16 vertices of one block, one frame: p = rest + c, out = M [p; 1] in
// float (M: the 12 blended entries, 16 lanes each), interleaved x y z and
// widened to double: 48 doubles at dst, the first `count` of them.
__attribute__((target("avx512f,fma"), always_inline)) inline void finishBlock(
    __m512 m0, __m512 m1, __m512 m2, __m512 m3, __m512 m4, __m512 m5, __m512 m6, __m512 m7,
    __m512 m8, __m512 m9, __m512 m10, __m512 m11, const float* rest, const float* c, double* dst,
    int count) {
  const __m512 px = _mm512_add_ps(_mm512_load_ps(rest), _mm512_load_ps(c));
  const __m512 py = _mm512_add_ps(_mm512_load_ps(rest + kL), _mm512_load_ps(c + kL));
  const __m512 pz = _mm512_add_ps(_mm512_load_ps(rest + 2 * kL), _mm512_load_ps(c + 2 * kL));
  const __m512 x = _mm512_fmadd_ps(m0, px, _mm512_fmadd_ps(m1, py, _mm512_fmadd_ps(m2, pz, m3)));
  const __m512 y = _mm512_fmadd_ps(m4, px, _mm512_fmadd_ps(m5, py, _mm512_fmadd_ps(m6, pz, m7)));
  const __m512 z = _mm512_fmadd_ps(m8, px, _mm512_fmadd_ps(m9, py, _mm512_fmadd_ps(m10, pz, m11)));
  // Output float e = 16 q + k holds component e % 3 of vertex e / 3: first
  // x and y by one two-source permute, then z into the remaining lanes.
  const __m512i xy0 = _mm512_set_epi32(5, 0, 20, 4, 0, 19, 3, 0, 18, 2, 0, 17, 1, 0, 16, 0),
                xyz0 = _mm512_set_epi32(15, 20, 13, 12, 19, 10, 9, 18, 7, 6, 17, 4, 3, 16, 1, 0),
                xy1 = _mm512_set_epi32(26, 10, 0, 25, 9, 0, 24, 8, 0, 23, 7, 0, 22, 6, 0, 21),
                xyz1 = _mm512_set_epi32(15, 14, 25, 12, 11, 24, 9, 8, 23, 6, 5, 22, 3, 2, 21, 0),
                xy2 = _mm512_set_epi32(0, 31, 15, 0, 30, 14, 0, 29, 13, 0, 28, 12, 0, 27, 11, 0),
                xyz2 = _mm512_set_epi32(31, 14, 13, 30, 11, 10, 29, 8, 7, 28, 5, 4, 27, 2, 1, 26);
  const __m512 o[3] = {_mm512_permutex2var_ps(_mm512_permutex2var_ps(x, xy0, y), xyz0, z),
                       _mm512_permutex2var_ps(_mm512_permutex2var_ps(x, xy1, y), xyz1, z),
                       _mm512_permutex2var_ps(_mm512_permutex2var_ps(x, xy2, y), xyz2, z)};
  for (int q = 0; q < 3; ++q) {
    const __m512d lo = _mm512_cvtps_pd(_mm512_castps512_ps256(o[q]));
    const __m512d hi =
        _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(o[q]), 1)));
    if (count >= 16 * q + 16) {
      _mm512_storeu_pd(dst + 16 * q, lo), _mm512_storeu_pd(dst + 16 * q + 8, hi);
    } else {
      _mm512_mask_storeu_pd(dst + 16 * q, laneMask(count - 16 * q), lo);
      _mm512_mask_storeu_pd(dst + 16 * q + 8, laneMask(count - 16 * q - 8), hi);
    }
  }
}

// One step's skinning, every frame. joints/w: the step's joint list and
// its 32 weights per entry; rest: the step's packed rest positions (96
// doubles); corr: the step's correctives (96 per frame); out + t*ld: frame
// t's 3N doubles.
__attribute__((target("avx512f,fma"))) void skinAvx512(const SkinStep& a) {
  const ptrdiff_t* const joints = a.joints;
  const float* const w = a.w;
  const float* const rest = a.rest32;
  const int count = a.count, first = a.first, frames = a.frames, k = a.k;
  const float* const corr = a.corr;
  const float* const transforms = a.transforms;
  double* const out = a.out;
  const size_t ld = a.ld;
  const int valid = imin(kStepVertices, a.n - first);
  for (int t = 0; t < frames; ++t) {
    const float* tr = transforms + static_cast<size_t>(t) * k * 12;
    __m512 m00 = _mm512_setzero_ps(), m01 = m00, m10 = m00, m11 = m00, m20 = m00, m21 = m00,
           m30 = m00, m31 = m00, m40 = m00, m41 = m00, m50 = m00, m51 = m00, m60 = m00, m61 = m00,
           m70 = m00, m71 = m00, m80 = m00, m81 = m00, m90 = m00, m91 = m00, ma0 = m00, ma1 = m00,
           mb0 = m00, mb1 = m00;
    for (int e = 0; e < count; ++e) {
      const __m512 w0 = _mm512_load_ps(w + 32 * e), w1 = _mm512_load_ps(w + 32 * e + 16);
      const float* tj = tr + joints[e];
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
    const float* c = corr + static_cast<size_t>(t) * kStepRows;
    double* dst = out + static_cast<size_t>(t) * ld + 3 * static_cast<size_t>(first);
    finishBlock(m00, m10, m20, m30, m40, m50, m60, m70, m80, m90, ma0, mb0, rest, c, dst,
                3 * imin(kL, valid));
    if (valid > kL)
      finishBlock(m01, m11, m21, m31, m41, m51, m61, m71, m81, m91, ma1, mb1, rest + 3 * kL,
                  c + 3 * kL, dst + 3 * kL, 3 * (valid - kL));
  }
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

// The step's 96 rows for `tiles` tiles of 6 frames (b: depth x 6 each),
// panel by panel (a panel, 13 KB, stays in L1 over the tiles); before each
// panel a sixth of the next step's lines pf and of the result lines pw[].
__attribute__((target("avx2,fma"))) void gemmAvx2(const float* a, int depth, const float* b,
                                                  int tiles, float* corr, const char* pf,
                                                  int pf_lines, char* const* pw, int pw_lines,
                                                  ptrdiff_t pw_offset) {
  const size_t ps = static_cast<size_t>(depth) * kL;
  for (int q = 0; q < 6; ++q) {
    for (int l = q * pf_lines / 6; l < (q + 1) * pf_lines / 6; ++l)
      _mm_prefetch(pf + 64 * l, _MM_HINT_T1);
    for (int l = q * pw_lines / 6; l < (q + 1) * pw_lines / 6; ++l)
      __builtin_prefetch(pw[l] + pw_offset, 1, 3);
    for (int t = 0; t < tiles; ++t)
      tile16x6(a + q * ps, b + static_cast<size_t>(t) * depth * 6, depth,
               corr + static_cast<size_t>(t) * 6 * kStepRows + kL * q);
  }
}

// 8 vertices per step of the loop, 12 blended entries in 12 named
// registers; the transform one vertex at a time.
__attribute__((target("avx2,fma"))) void skinAvx2(const SkinStep& a) {
  const ptrdiff_t* const joints = a.joints;
  const float* const w = a.w;
  const int count = a.count, first = a.first, frames = a.frames, k = a.k;
  const float* const corr = a.corr;
  const float* const transforms = a.transforms;
  double* const out = a.out;
  const size_t ld = a.ld;
  const int valid = imin(kStepVertices, a.n - first);
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
        const float* tj = tr + joints[e];
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
      const int at = 3 * kL * (g / 2) + 8 * (g % 2);  // the group's x in corr and rest
      const float* cg = c + at;
      const double* rg = a.rest64 + at;
      for (int l = 0; l < 8 && 8 * g + l < valid; ++l)
        transformVertex(&m[0][l], 8, rg[l] + cg[l], rg[kL + l] + cg[kL + l],
                        rg[2 * kL + l] + cg[2 * kL + l], dst + 3 * (first + 8 * g + l));
    }
  }
}

#endif  // SMPL_X86_KERNELS

// ---------------------------------------------------------------- portable

// b is one tile of all `cols` frames (b[cols * p + j]).
void gemmPortable(const float* a, int depth, const float* b, int cols, float* corr, const char*,
                  int, char* const*, int, ptrdiff_t) {
  const size_t ps = static_cast<size_t>(depth) * kL;
  const Eigen::Map<const Eigen::MatrixXf> ft(b, cols, depth);  // frames x features
  for (int q = 0; q < 6; ++q) {
    Eigen::Map<Eigen::MatrixXf, 0, Eigen::OuterStride<>> c(corr + kL * q, kL, cols,
                                                           Eigen::OuterStride<>(kStepRows));
    c.noalias() = Eigen::Map<const Eigen::MatrixXf>(a + q * ps, kL, depth) * ft.transpose();
  }
}

// The blend joint by joint over the step's 32 lanes (loops the compiler
// vectorises with the baseline instruction set), then each vertex in double.
void skinPortable(const SkinStep& a) {
  const int valid = std::min(kStepVertices, a.n - a.first);
  for (int t = 0; t < a.frames; ++t) {
    const float* tr = a.transforms + static_cast<size_t>(t) * a.k * 12;
    const float* c = a.corr + static_cast<size_t>(t) * kStepRows;
    alignas(64) float m[12][kStepVertices] = {};
    for (int e = 0; e < a.count; ++e) {
      const float* we = a.w + kStepVertices * e;
      const float* tj = tr + a.joints[e];
      for (int q = 0; q < 12; ++q) {
        const float tq = tj[q];
        for (int l = 0; l < kStepVertices; ++l) m[q][l] += we[l] * tq;
      }
    }
    for (int l = 0; l < valid; ++l) {
      const int at = 3 * kL * (l / kL) + l % kL;  // x of lane l in corr and rest
      const float* cl = c + at;
      const double* rl = a.rest64 + at;
      transformVertex(&m[0][l], kStepVertices, rl[0] + cl[0], rl[kL] + cl[kL],
                      rl[2 * kL] + cl[2 * kL],
                      a.out + static_cast<size_t>(t) * a.ld + 3 * (a.first + l));
    }
  }
}

// ---------------------------------------------------------------- dispatch

using GemmFn = void (*)(const float*, int, const float*, int, float*, const char*, int,
                        char* const*, int, ptrdiff_t);
using SkinFn = void (*)(const SkinStep&);
struct KernelSet {
  GemmFn gemm;
  SkinFn skin;
  int tile_cols;  // frames per GEMM tile; 0: one tile of the whole block
};

KernelSet kernelSet(Kernels kernels) {
  switch (kernels) {
#if SMPL_X86_KERNELS
    case Kernels::Avx512:
      return {&gemmAvx512, &skinAvx512, 8};
    case Kernels::Avx2:
      return {&gemmAvx2, &skinAvx2, 6};
#endif
    default:
      return {&gemmPortable, &skinPortable, 0};
  }
}

bool haveAvx2Fma() {
#if SMPL_X86_KERNELS
  static const bool have = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return have;
#else
  return false;
#endif
}

bool haveAvx512() {  // libgcc checks that the OS saves the zmm and mask state
#if SMPL_X86_KERNELS
  static const bool have = haveAvx2Fma() && __builtin_cpu_supports("avx512f");
  return have;
#else
  return false;
#endif
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

PackedPosedirs packPosedirs(const double* posedirs, int vertices, int depth, int threads) {
  PackedPosedirs a;
  a.vertices = vertices;
  a.depth = depth;
  a.steps = (vertices + kStepVertices - 1) / kStepVertices;
  const int blocks = 2 * a.steps;
  a.data.resize(static_cast<size_t>(blocks) * 3 * depth * kL);  // every element written below
  adviseHugePages(a.data.data(), a.data.size() * sizeof(float));
  const size_t rows = 3 * static_cast<size_t>(vertices);
  // Feature by feature: each posedirs column is read in order, and each
  // destination write is one whole cache line (16 floats).
  runWorkers(std::max(1, std::min(threads, depth)), [&](int worker, int workers) {
    for (int p = worker; p < depth; p += workers) {
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
  });
  return a;
}

PackedRest packRest(const double* v_shaped, int vertices) {
  const int steps = (vertices + kStepVertices - 1) / kStepVertices;
  PackedRest rest;
  rest.f64.resize(static_cast<size_t>(steps) * kStepRows);
  rest.f32.resize(rest.f64.size());
  for (int s = 0; s < steps; ++s)
    for (int h = 0; h < 2; ++h)
      for (int d = 0; d < 3; ++d)
        for (int l = 0; l < kL; ++l) {
          const int i = s * kStepVertices + h * kL + l;
          const size_t at = static_cast<size_t>(s) * kStepRows + 3 * kL * h + kL * d + l;
          rest.f64[at] = i < vertices ? v_shaped[static_cast<size_t>(d) * vertices + i] : 0.0;
          rest.f32[at] = static_cast<float>(rest.f64[at]);
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
      s.offsets.push_back(12 * static_cast<ptrdiff_t>(j));
      s.w.insert(s.w.end(), w, w + kStepVertices);
    }
    s.begin.push_back(static_cast<int>(s.joints.size()));
  }
  return s;
}

void evaluateBlock(const PackedPosedirs& posedirs, const std::vector<const PackedSkin*>& skins,
                   const PackedRest& rest, const FrameBlock& block, double* const* out, size_t ld,
                   Kernels kernels) {
  const KernelSet ks = kernelSet(resolveKernels(kernels));  // never one the CPU lacks
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
  // Step by step: the GEMM of all frames, then their skinning.
  AlignedVector<float> corr(static_cast<size_t>(kStepRows) * cols, 0.0f);
  // The result lines the step's skinning will write (every skin and frame),
  // prefetched for writing by the step's GEMM so the result's memory
  // traffic overlaps the multiply-adds instead of stalling the skinning's
  // stores. Listed for the first step; step s's are 96 doubles further on
  // (the same count: a column's alignment is the same for every step; the
  // last step's extra lines are prefetches nobody needs). Padded with
  // depth / 4 + 1 copies of the last line, so the GEMM tiles need no test.
  std::vector<char*> lines;
  if (ks.tile_cols > 0) {
    for (size_t i = 0; i < skins.size(); ++i)
      for (int t = 0; t < frames; ++t) {
        const uintptr_t col = reinterpret_cast<uintptr_t>(out[i] + t * ld);
        for (uintptr_t l = col & ~uintptr_t(63); l < col + 8 * kStepRows; l += 64)
          lines.push_back(reinterpret_cast<char*>(l));
      }
  }
  const int line_count = static_cast<int>(lines.size());
  lines.resize(lines.size() + depth / 4 + 1,
               line_count > 0 ? lines.back() : reinterpret_cast<char*>(corr.data()));
  const size_t step_floats = static_cast<size_t>(6) * depth * kL;
  const int step_lines = static_cast<int>(step_floats / 16);
  for (int s = 0; s < posedirs.steps; ++s) {
    const float* a = posedirs.data.data() + s * step_floats;
    // The next step's panels (past the last step: prefetches of lines
    // nobody reads, harmless).
    const char* next = reinterpret_cast<const char*>(a + step_floats);
    const ptrdiff_t pw_offset = line_count > 0 ? 8 * kStepRows * static_cast<ptrdiff_t>(s) : 0;
    if (depth > 0)
      ks.gemm(a, depth, b.data(), ks.tile_cols > 0 ? tiles : cols, corr.data(), next, step_lines,
              lines.data(), line_count, pw_offset);
    {
      const int t0 = 0, nr = frames;
      for (size_t i = 0; i < skins.size(); ++i) {
        const PackedSkin& sk = *skins[i];
        const int e0 = sk.begin[s];
        SkinStep step;
        step.joints = sk.offsets.data() + e0;
        step.count = sk.begin[s + 1] - e0;
        step.w = sk.w.data() + static_cast<size_t>(e0) * kStepVertices;
        step.first = s * kStepVertices;
        step.n = n;
        step.rest64 = rest.f64.data() + static_cast<size_t>(s) * kStepRows;
        step.rest32 = rest.f32.data() + static_cast<size_t>(s) * kStepRows;
        step.corr = corr.data() + static_cast<size_t>(t0) * kStepRows;
        step.frames = nr;
        step.transforms = block.transforms + static_cast<size_t>(t0) * block.joints * 12;
        step.k = block.joints;
        step.out = out[i] + static_cast<size_t>(t0) * ld;
        step.ld = ld;
        ks.skin(step);
      }
    }
  }
}

}  // namespace batch
}  // namespace smpl
