// Matrix products whose every output is summed in one fixed order, so the
// same inputs give the same bits on every CPU, vector width and build
// (x86-64 scalar, SSE4, AVX2, AVX-512; WebAssembly; Windows):
//
//   C(i, j) = (...((0 + A(i,0) B(0,j)) + A(i,1) B(1,j)) + ...) + A(i,k-1) B(k-1,j)
//
// each step a rounded multiply, then a rounded add (never a fused
// multiply-add: the kernels are compiled without FMA and with
// -ffp-contract=off). The kernels vectorise across independent outputs (rows
// of C), never across the sum, so a lane computes exactly what the scalar
// code computes; register tiles only change which outputs are computed
// together. The target is core/math/simd_target.h's active one.
// Eigen's own products split the sum by the CPU's vector width (and its
// blocking by the cache sizes), which is why the outputs' hot products use
// these instead.
#pragma once

#include <Eigen/Core>

namespace smpl {

// c = a b: a (m x k), b (k x n), c (m x n) resized; column-major, any
// leading dimension (blocks and maps of matrices are fine). No aliasing of
// c with a or b. Units are the caller's; cost m n k multiply-adds.
void fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                       const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd* c);

// The same, returned.
Eigen::MatrixXd fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b);

// The same in float (each step rounded to float): twice the lanes of a
// register, for products whose error budget allows 24-bit sums.
void fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXf>& a,
                       const Eigen::Ref<const Eigen::MatrixXf>& b, Eigen::MatrixXf* c);
Eigen::MatrixXf fixedOrderProduct(const Eigen::Ref<const Eigen::MatrixXf>& a,
                                  const Eigen::Ref<const Eigen::MatrixXf>& b);

}  // namespace smpl
