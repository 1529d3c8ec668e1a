#include "core/math/skin_weights.h"

#include <gtest/gtest.h>

namespace smpl {
namespace {

TEST(PruneWeights, KeepsLargestAndRenormalises) {
  Eigen::MatrixXd w(1, 6);
  w << 0.05, 0.3, 0.1, 0.25, 0.2, 0.1;
  SparseSkin s = pruneWeights(w, 4);
  ASSERT_EQ(s.joints.cols(), 4);
  EXPECT_EQ(s.joints(0, 0), 1);
  EXPECT_EQ(s.joints(0, 1), 3);
  EXPECT_EQ(s.joints(0, 2), 4);
  EXPECT_EQ(s.joints(0, 3), 2);  // tie 0.1 vs 0.1: lower joint index wins
  EXPECT_NEAR(s.weights.row(0).sum(), 1.0, 1e-15);
  EXPECT_NEAR(s.weights(0, 0), 0.3 / 0.85, 1e-15);
}

TEST(PruneWeights, FewerNonzeroThanSlotsLeavesZeroSlots) {
  Eigen::MatrixXd w(1, 3);
  w << 0.0, 1.0, 0.0;
  SparseSkin s = pruneWeights(w, 4);
  EXPECT_EQ(s.joints(0, 0), 1);
  EXPECT_EQ(s.weights(0, 0), 1.0);
  EXPECT_EQ(s.weights(0, 1), 0.0);
  EXPECT_EQ(s.joints(0, 1), 0);
}

TEST(PruneWeights, DenseRoundTrip) {
  Eigen::MatrixXd w = Eigen::MatrixXd::Random(20, 7).cwiseAbs();
  for (int i = 0; i < 20; ++i) w.row(i) /= w.row(i).sum();
  Eigen::MatrixXd back = denseWeights(pruneWeights(w, 7), 7);
  EXPECT_LT((back - w).cwiseAbs().maxCoeff(), 1e-15);
}

}  // namespace
}  // namespace smpl
