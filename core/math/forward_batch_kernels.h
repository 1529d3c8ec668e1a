// The inner loops of forwardBatch (core/math/forward_batch.h), written out
// for the CPU in three kernel sets, chosen at run time from what the CPU
// reports (cpuid, and the OS saving the vector state):
//  - Avx512: AVX-512F + FMA, 16 float lanes per register;
//  - Avx2: AVX2 + FMA, 8 lanes;
//  - Portable: Eigen's products and plain loops (SSE2 on x86-64).
// All three compute the corrective product and the blend in float, the
// final transform in double (Avx2, Portable) or in float widened to double
// (Avx512); order may differ per element; tests compare each set with
// forward() (<= 4e-7 m in them). No Eigen inside the AVX functions
// (target("...")), so no template compiled for a newer instruction set can
// be merged into code run on older CPUs.
//
// Layout. Vertices are taken 32 at a time (a "step": two 16-vertex blocks).
// posedirs is packed into float panels of 16 rows, one panel per (block,
// component): panel 3b+d holds component d (x, y, z) of vertices [16b,
// 16b+16) for every pose feature, feature-major, so the corrective product
// of a step is a (96 x P)(P x T) GEMM whose result is already split by
// component, as the skinning wants it. The skin weights are packed per
// step: only the joints that weigh on some vertex of the step, 32 weights
// each (pruned or sparse weights skip the rest). All packed data is 64-byte
// aligned (no vector load splits a cache line).
//
// One block of T frames (evaluateBlock) runs step by step, so a step's
// correctives (96 x T floats) go from the GEMM to the skinning in L1/L2:
//  1. GEMM: the step's 6 panels (80 KB) times the block's packed pose
//     features: Avx512 in 48 x 8 register tiles (a block's 3 panels x 8
//     frames, 24 zmm accumulators: 3 loads and 8 broadcasts per 24 FMAs),
//     block-major so a block's panels (40 KB) stay in L1 over the frames;
//     Avx2 in 16 x 6 tiles (12 ymm accumulators); Portable by Eigen.
//     posedirs streams from memory once per block of frames; on the way
//     the GEMM prefetches the next step's panels into L2 and, for writing,
//     the result lines the step's skinning will store, so the memory
//     traffic of the result (3N doubles a frame) overlaps the arithmetic.
//  2. Skinning, per frame: the blended transforms of the 32 vertices,
//     M_i = sum_k w_ik T_k (12 floats each), as a 32 x 12 register tile over
//     the step's joints (Avx512: 24 zmm accumulators, 2 weight loads and 12
//     broadcasts per 24 FMAs; Avx2: 8 x 12 in 12 ymm), then
//     out_i = M_i [v_shaped_i + c_i; 1] (Avx512: in float on 16 vertices,
//     interleaved x y z, widened to double; Avx2 and Portable: in double,
//     one vertex at a time).
//
// Cost per frame for the 6890-vertex, 207-feature, 24-joint SMPL layout with
// dense weights: the corrective product is 3N*P = 4.28 M multiply-adds, the
// blend 12 per non-zero weight = N*K*12 = 1.98 M, the final transform 12 per
// vertex = 0.08 M; 6.35 M in all: 0.053 ms at this machine's measured
// single-core AVX-512 peak of ~120 G multiply-adds/s (0.057 ms at the ~112
// G/s it measures while the other core is busy). The Avx512 kernels take
// 0.070-0.083 ms/frame in smpl-bench --compare runs with other builds on the
// machine (1.35-1.43x the limit), 0.065-0.071 in quieter moments; 97% of
// that time is the two kernels (GEMM ~63%, skinning ~34%; perf), each at
// ~75-85% of the FMA peak (the GEMM loop alone, data in cache: ~85%; plus
// posedirs streaming from memory). The rest (kinematic chain, pose
// features, packing the weights) is ~2% per frame; packing posedirs (34 MB
// read, 17 MB written for SMPL) is once per call or once for many
// (BatchInput::posedirs).
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace smpl {

// Which kernel set forwardBatch runs. Best: the widest the CPU runs
// (Avx512, else Avx2, else Portable), decided at run time. An explicit set
// the CPU lacks is never called: it resolves to Best (resolveKernels), and
// forwardBatch does the same, so asking for Avx512 on an AVX2 CPU runs Avx2.
enum class Kernels { Best, Portable, Avx2, Avx512 };

namespace batch {

// True if the CPU (and OS) run this set; Best and Portable always.
bool cpuRuns(Kernels kernels);
// The set that will run for a request: the request if the CPU runs it and it
// is not Best, else the widest the CPU runs. Never returns Best.
Kernels resolveKernels(Kernels requested);
// The concrete sets the CPU runs, narrowest first (Portable first).
std::vector<Kernels> supportedKernels();
const char* kernelsName(Kernels kernels);  // "portable", "avx2", "avx512"

// 64-byte aligned storage (whole cache lines, no split vector loads), not
// zero-filled on resize: the packers write every element.
template <typename T>
struct Aligned64 {
  using value_type = T;
  Aligned64() = default;
  template <typename U>
  Aligned64(const Aligned64<U>&) {}
  T* allocate(size_t n) {
    return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(64)));
  }
  void deallocate(T* p, size_t) { ::operator delete(p, std::align_val_t(64)); }
  template <typename U>
  void construct(U* p) {  // default-initialise: no zero fill
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(static_cast<Args&&>(args)...);
  }
  bool operator==(const Aligned64&) const { return true; }
  bool operator!=(const Aligned64&) const { return false; }
};
template <typename T>
using AlignedVector = std::vector<T, Aligned64<T>>;

// Large fresh buffers (a 169 MB result for 1024 SMPL frames, packed
// posedirs) are first touched one 4 KiB page at a time: a page fault each,
// about as much time as the arithmetic; they ask for transparent huge pages
// (core/huge_pages.h) before the first write.

constexpr int kBlockVertices = 16;                 // vertices per panel
constexpr int kStepVertices = 2 * kBlockVertices;  // vertices per step
constexpr int kStepRows = 3 * kStepVertices;       // corrective rows per step (96)

// posedirs (3N x P, column-major doubles, row 3i+d = component d of vertex
// i) as float panels: component d of vertex 16b+l, feature p at
// data[((3b + d) * depth + p) * 16 + l]; blocks rounded up to whole steps,
// vertices past N zero.
struct PackedPosedirs {
  AlignedVector<float> data;
  int vertices = 0;  // N
  int steps = 0;     // ceil(N / 32)
  int depth = 0;     // P
};
// On `threads` workers, feature by feature (each writes its own panels: the
// packed data does not depend on the count).
PackedPosedirs packPosedirs(const double* posedirs, int vertices, int depth, int threads = 1);

// Skin weights (N x K, column-major doubles) per step: the joints with a
// non-zero weight on any of the step's 32 vertices are
// joints[begin[s] .. begin[s+1]), entry e's 32 weights at w[32 e + lane]
// (vertices past N zero).
struct PackedSkin {
  std::vector<int> joints, begin;
  std::vector<ptrdiff_t> offsets;  // 12 * joints[e]: where entry e's transform starts
  AlignedVector<float> w;
  long long nonzeros = 0;  // non-zero weights in the matrix (the cost model's count)
};
PackedSkin packSkin(const double* weights, int vertices, int joints);

// v_shaped (N x 3, column-major doubles) per step, in the correctives'
// layout: component d of vertex 32 s + 16 h + l at [96 s + 48 h + 16 d + l],
// zero past N; in double and rounded to float.
struct PackedRest {
  AlignedVector<double> f64;
  AlignedVector<float> f32;
};
PackedRest packRest(const double* v_shaped, int vertices);

// One block of frames through the whole pass.
struct FrameBlock {
  const float* features = nullptr;    // P x frames, column-major: the pose features
  const float* transforms = nullptr;  // frames x K x 12: frame t, joint k at (t*K + k)*12,
                                      // the top 3x4 rows of G_k [I | -J_k], row by row
  int frames = 0;
  int joints = 0;  // K
};
// For every skin s and frame t: out[s] + t * ld receives frame t's 3N
// vertex coordinates (x0 y0 z0 x1 ...) in double, metres:
// out_i = (sum_k w_ik T_k) [v_shaped_i + c_i; 1], c = posedirs * f.
// rest: packRest(v_shaped). kernels: as for forwardBatch (resolveKernels).
void evaluateBlock(const PackedPosedirs& posedirs, const std::vector<const PackedSkin*>& skins,
                   const PackedRest& rest, const FrameBlock& block, double* const* out, size_t ld,
                   Kernels kernels);

}  // namespace batch
}  // namespace smpl
