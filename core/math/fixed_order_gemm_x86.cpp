// fixedOrderProduct's SSE4, AVX2 and AVX-512 kernels (fixed_order_gemm.h):
// the one kernel (fixed_order_gemm_kernel.inc) over 2, 4 and 8 double
// lanes and 4, 8 and 16 float lanes, each compiled for its instruction set only (no FMA: multiply,
// then add; the file is compiled with -ffp-contract=off, core/CMakeLists.txt).
#include "core/math/fixed_order_gemm_targets.h"

#if SMPL_FIXED_ORDER_X86
#include <immintrin.h>

#include <cstddef>

namespace smpl {
namespace fixed_order {

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("sse4.1"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("sse4.1")
#endif
namespace sse4 {
struct V {
  using scalar = double;
  using reg = __m128d;
  static constexpr int L = 2;
  static reg zero() { return _mm_setzero_pd(); }
  static reg load(const double* p) { return _mm_loadu_pd(p); }
  static reg set1(double x) { return _mm_set1_pd(x); }
  static reg mul(reg a, reg b) { return _mm_mul_pd(a, b); }
  static reg add(reg a, reg b) { return _mm_add_pd(a, b); }
  static void store(double* p, reg v) { _mm_storeu_pd(p, v); }
};
struct F {
  using scalar = float;
  using reg = __m128;
  static constexpr int L = 4;
  static reg zero() { return _mm_setzero_ps(); }
  static reg load(const float* p) { return _mm_loadu_ps(p); }
  static reg set1(float x) { return _mm_set1_ps(x); }
  static reg mul(reg a, reg b) { return _mm_mul_ps(a, b); }
  static reg add(reg a, reg b) { return _mm_add_ps(a, b); }
  static void store(float* p, reg v) { _mm_storeu_ps(p, v); }
};
#include "core/math/fixed_order_gemm_kernel.inc"
}  // namespace sse4
void gemmSse4(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
              std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
              std::ptrdiff_t ldc) {
  sse4::gemm<sse4::V>(m, n, k, a, lda, b, ldb, c, ldc);
}
void gemmSse4(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
              std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c,
              std::ptrdiff_t ldc) {
  sse4::gemm<sse4::F>(m, n, k, a, lda, b, ldb, c, ldc);
}
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2 {
struct V {
  using scalar = double;
  using reg = __m256d;
  static constexpr int L = 4;
  static reg zero() { return _mm256_setzero_pd(); }
  static reg load(const double* p) { return _mm256_loadu_pd(p); }
  static reg set1(double x) { return _mm256_set1_pd(x); }
  static reg mul(reg a, reg b) { return _mm256_mul_pd(a, b); }
  static reg add(reg a, reg b) { return _mm256_add_pd(a, b); }
  static void store(double* p, reg v) { _mm256_storeu_pd(p, v); }
};
struct F {
  using scalar = float;
  using reg = __m256;
  static constexpr int L = 8;
  static reg zero() { return _mm256_setzero_ps(); }
  static reg load(const float* p) { return _mm256_loadu_ps(p); }
  static reg set1(float x) { return _mm256_set1_ps(x); }
  static reg mul(reg a, reg b) { return _mm256_mul_ps(a, b); }
  static reg add(reg a, reg b) { return _mm256_add_ps(a, b); }
  static void store(float* p, reg v) { _mm256_storeu_ps(p, v); }
};
#include "core/math/fixed_order_gemm_kernel.inc"
}  // namespace avx2
void gemmAvx2(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
              std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
              std::ptrdiff_t ldc) {
  avx2::gemm<avx2::V>(m, n, k, a, lda, b, ldb, c, ldc);
}
void gemmAvx2(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
              std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c,
              std::ptrdiff_t ldc) {
  avx2::gemm<avx2::F>(m, n, k, a, lda, b, ldb, c, ldc);
}
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f")
#endif
namespace avx512 {
struct V {
  using scalar = double;
  using reg = __m512d;
  static constexpr int L = 8;
  static reg zero() { return _mm512_setzero_pd(); }
  static reg load(const double* p) { return _mm512_loadu_pd(p); }
  static reg set1(double x) { return _mm512_set1_pd(x); }
  static reg mul(reg a, reg b) { return _mm512_mul_pd(a, b); }
  static reg add(reg a, reg b) { return _mm512_add_pd(a, b); }
  static void store(double* p, reg v) { _mm512_storeu_pd(p, v); }
};
struct F {
  using scalar = float;
  using reg = __m512;
  static constexpr int L = 16;
  static reg zero() { return _mm512_setzero_ps(); }
  static reg load(const float* p) { return _mm512_loadu_ps(p); }
  static reg set1(float x) { return _mm512_set1_ps(x); }
  static reg mul(reg a, reg b) { return _mm512_mul_ps(a, b); }
  static reg add(reg a, reg b) { return _mm512_add_ps(a, b); }
  static void store(float* p, reg v) { _mm512_storeu_ps(p, v); }
};
#include "core/math/fixed_order_gemm_kernel.inc"
}  // namespace avx512
void gemmAvx512(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
                std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
                std::ptrdiff_t ldc) {
  avx512::gemm<avx512::V>(m, n, k, a, lda, b, ldb, c, ldc);
}
void gemmAvx512(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
                std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c,
                std::ptrdiff_t ldc) {
  avx512::gemm<avx512::F>(m, n, k, a, lda, b, ldb, c, ldc);
}
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

}  // namespace fixed_order
}  // namespace smpl
#endif  // SMPL_FIXED_ORDER_X86
