// fixedOrderProduct (fixed_order_gemm.h): the scalar kernel (every build,
// the only one in WebAssembly) and the dispatch to the active target's.
#include "core/math/fixed_order_gemm.h"

#include <cstddef>

#include "core/math/fixed_order_gemm_targets.h"
#include "core/math/simd_target.h"

namespace smpl {
namespace fixed_order {
namespace scalar {
#include "core/math/fixed_order_gemm_kernel.inc"
}  // namespace scalar

void gemmScalar(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const double* a,
                std::ptrdiff_t lda, const double* b, std::ptrdiff_t ldb, double* c,
                std::ptrdiff_t ldc) {
  scalar::gemm<scalar::Lanes1<double>>(m, n, k, a, lda, b, ldb, c, ldc);
}

void gemmScalar(std::ptrdiff_t m, std::ptrdiff_t n, std::ptrdiff_t k, const float* a,
                std::ptrdiff_t lda, const float* b, std::ptrdiff_t ldb, float* c,
                std::ptrdiff_t ldc) {
  scalar::gemm<scalar::Lanes1<float>>(m, n, k, a, lda, b, ldb, c, ldc);
}

namespace {

template <class T>
GemmFn<T> kernelOf(SimdTarget target) {
  switch (target) {
#if SMPL_FIXED_ORDER_X86
    case SimdTarget::Sse4:
      return &gemmSse4;
    case SimdTarget::Avx2:
      return &gemmAvx2;
    case SimdTarget::Avx512:
      return &gemmAvx512;
#endif
    default:
      return &gemmScalar;
  }
}

}  // namespace
}  // namespace fixed_order

namespace {

template <class Matrix>
void product(const Eigen::Ref<const Matrix>& a, const Eigen::Ref<const Matrix>& b, Matrix* c) {
  eigen_assert(a.cols() == b.rows());
  c->resize(a.rows(), b.cols());
  if (c->size() == 0) return;
  if (a.cols() == 0) {  // an empty sum (and data() may be null: no pointer arithmetic on it)
    c->setZero();
    return;
  }
  fixed_order::kernelOf<typename Matrix::Scalar>(activeSimdTarget())(
      a.rows(), b.cols(), a.cols(), a.data(), a.outerStride(), b.data(), b.outerStride(), c->data(),
      c->rows());
}

}  // namespace

void fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                       const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd* c) {
  product<Eigen::MatrixXd>(a, b, c);
}

Eigen::MatrixXd fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b) {
  Eigen::MatrixXd c;
  fixedOrderProduct(a, b, &c);
  return c;
}

void fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXf>& a,
                       const Eigen::Ref<const Eigen::MatrixXf>& b, Eigen::MatrixXf* c) {
  product<Eigen::MatrixXf>(a, b, c);
}

Eigen::MatrixXf fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXf>& a,
                                  const Eigen::Ref<const Eigen::MatrixXf>& b) {
  Eigen::MatrixXf c;
  fixedOrderProduct(a, b, &c);
  return c;
}

}  // namespace smpl
