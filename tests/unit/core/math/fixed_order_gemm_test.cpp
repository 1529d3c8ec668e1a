// fixedOrderProduct (core/math/fixed_order_gemm.h) and the SIMD target
// switch (core/math/simd_target.h): every target this CPU runs gives the
// bits of the scalar definition, sum_p in order, multiply then add.
#include "core/math/fixed_order_gemm.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <random>

#include "core/math/simd_target.h"

namespace smpl {
namespace {

// The definition, written out: one rounded multiply and one rounded add per term.
template <class Matrix>
Matrix definition(const Matrix& a, const Matrix& b) {
  using T = typename Matrix::Scalar;
  Matrix c(a.rows(), b.cols());
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < b.cols(); ++j) {
      T s = 0;
      for (Eigen::Index p = 0; p < a.cols(); ++p) {
        volatile T term = a(i, p) * b(p, j);  // volatile: never fused with the add
        s = s + term;
      }
      c(i, j) = s;
    }
  return c;
}

template <class Matrix>
bool sameBits(const Matrix& x, const Matrix& y) {
  return x.rows() == y.rows() && x.cols() == y.cols() &&
         std::memcmp(x.data(), y.data(), sizeof(typename Matrix::Scalar) * size_t(x.size())) == 0;
}

// Restores the widest target after a test that forced one.
struct TargetReset {
  ~TargetReset() {
    const std::vector<SimdTarget> all = supportedSimdTargets();
    EXPECT_TRUE(selectSimdTarget(simdTargetName(all.back())).ok());
  }
};

// Random products of every shape class (tiles, leftover rows and columns, k
// = 0, a leading dimension other than the rows) on every target: the bits of
// the definition. Matrix: MatrixXd or MatrixXf.
template <class Matrix>
void expectEveryTargetGivesTheDefinitionsBits(double tolerance) {
  using T = typename Matrix::Scalar;
  TargetReset reset;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> size(0, 37);
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 1 + size(rng), n = 1 + size(rng) / 2, k = trial == 0 ? 0 : size(rng) * 3;
    // Values over many magnitudes, so that another order of the sums would round differently.
    Matrix a(m + 3, k), b(k, n);
    for (Eigen::Index e = 0; e < a.size(); ++e)
      a.data()[e] = T(normal(rng) * std::exp2(size(rng) - 18));
    for (Eigen::Index e = 0; e < b.size(); ++e) b.data()[e] = T(normal(rng));
    // A leading dimension other than the rows: a block of a taller matrix
    // (k = 0: a plain empty matrix; a block of one would offset a null pointer).
    const Matrix empty(m, 0);
    const Eigen::Ref<const Matrix> a_block =
        k > 0 ? Eigen::Ref<const Matrix>(a.middleRows(2, m)) : Eigen::Ref<const Matrix>(empty);
    const Matrix expected = definition<Matrix>(a_block, b);
    for (SimdTarget t : supportedSimdTargets()) {
      ASSERT_TRUE(selectSimdTarget(simdTargetName(t)).ok());
      const Matrix c = fixedOrderProduct(a_block, b);
      EXPECT_TRUE(sameBits(c, expected))
          << simdTargetName(t) << " m " << m << " n " << n << " k " << k;
      if (k == 0) continue;  // the bits above are the zeros of an empty sum
      const double scale = double((a_block.cwiseAbs() * b.cwiseAbs()).maxCoeff());
      EXPECT_LE(double((c - a_block * b).cwiseAbs().maxCoeff()), tolerance * scale)
          << simdTargetName(t);
    }
  }
}

TEST(FixedOrderGemm, EveryTargetGivesTheDefinitionsBits) {
  expectEveryTargetGivesTheDefinitionsBits<Eigen::MatrixXd>(1e-13);
}

TEST(FixedOrderGemm, EveryTargetGivesTheDefinitionsBitsInFloat) {
  expectEveryTargetGivesTheDefinitionsBits<Eigen::MatrixXf>(1e-4);
}

TEST(FixedOrderGemm, OrderIsVisible) {
  // The test above could not tell a sum in another order from the definition
  // if its values rounded the same either way: this one cannot.
  Eigen::MatrixXd a(1, 3), b(3, 1);
  a << 1e16, 1.0, -1e16;
  b << 1.0, 1.0, 1.0;
  EXPECT_EQ(fixedOrderProduct(a, b)(0, 0), 0.0);  // (1e16 + 1) - 1e16 = 0 in order
  EXPECT_EQ(a(0, 0) * b(0, 0) + a(0, 2) * b(2, 0) + a(0, 1) * b(1, 0), 1.0);  // another order
  Eigen::MatrixXf af(1, 3), bf(3, 1);  // in float: (1e8 + 1) - 1e8 = 0 in order
  af << 1e8f, 1.0f, -1e8f;
  bf << 1.0f, 1.0f, 1.0f;
  EXPECT_EQ(fixedOrderProduct(af, bf)(0, 0), 0.0f);
}

TEST(SimdTarget, NamesAndRefusals) {
  TargetReset reset;
  EXPECT_TRUE(cpuRunsSimd(SimdTarget::Scalar));
  EXPECT_EQ(supportedSimdTargets().front(), SimdTarget::Scalar);
  const Status unknown = selectSimdTarget("avx3");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.message().find("unknown target 'avx3'"), std::string::npos);
  EXPECT_EQ(unknown.kind(), ErrorKind::Usage);
  ASSERT_TRUE(selectSimdTarget("scalar").ok());
  EXPECT_EQ(activeSimdTarget(), SimdTarget::Scalar);
  for (SimdTarget t : {SimdTarget::Sse4, SimdTarget::Avx2, SimdTarget::Avx512})
    if (!cpuRunsSimd(t)) {
      const Status st = selectSimdTarget(simdTargetName(t));
      ASSERT_FALSE(st.ok());
      EXPECT_NE(st.message().find("not available on this CPU"), std::string::npos);
    }
}

TEST(SimdTarget, FromTheEnvironment) {
  TargetReset reset;
  ::setenv("SMPL_EXPORT_SIMD", "sse9\x01", 1);
  const Status bad = useSimdTargetFromEnvironment();
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message().rfind("SMPL_EXPORT_SIMD=sse9?: unknown target", 0), 0u) << bad.message();
  ::setenv("SMPL_EXPORT_SIMD", "scalar", 1);
  EXPECT_TRUE(useSimdTargetFromEnvironment().ok());
  EXPECT_EQ(activeSimdTarget(), SimdTarget::Scalar);
  ::unsetenv("SMPL_EXPORT_SIMD");
  EXPECT_TRUE(useSimdTargetFromEnvironment().ok());
  EXPECT_EQ(activeSimdTarget(), SimdTarget::Scalar);  // unset: nothing changes
}

}  // namespace
}  // namespace smpl
