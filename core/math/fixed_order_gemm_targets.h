// The per-target kernels behind fixedOrderProduct (fixed_order_gemm.h):
// raw column-major pointers, c = a b with a m x k (leading dimension lda),
// b k x n (ldb), c m x n (ldc); each in double and in float. Internal to
// core/math.
#pragma once

#include <cstddef>

// x86-64 kernels exist where GCC and clang's target attributes do; elsewhere
// (WebAssembly, other CPUs) the scalar kernel is the only one.
#if defined(__x86_64__) && defined(__GNUC__)
#define SMPL_FIXED_ORDER_X86 1
#else
#define SMPL_FIXED_ORDER_X86 0
#endif

namespace smpl {
namespace fixed_order {

template <class T>
using GemmFn = void (*)(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const T* a,
                        std::ptrdiff_t lda, const T* b, std::ptrdiff_t ldb, T* c,
                        std::ptrdiff_t ldc);

void gemmScalar(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
                std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
                std::ptrdiff_t ldc);
void gemmScalar(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
                std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c,
                std::ptrdiff_t ldc);
#if SMPL_FIXED_ORDER_X86
void gemmSse4(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
              std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
              std::ptrdiff_t ldc);
void gemmSse4(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
              std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c, std::ptrdiff_t ldc);
void gemmAvx2(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
              std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
              std::ptrdiff_t ldc);
void gemmAvx2(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
              std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c, std::ptrdiff_t ldc);
void gemmAvx512(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
                std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
                std::ptrdiff_t ldc);
void gemmAvx512(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
                std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c,
                std::ptrdiff_t ldc);
#endif

}  // namespace fixed_order
}  // namespace smpl
