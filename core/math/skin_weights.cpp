#include "core/math/skin_weights.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace smpl {

SparseSkin pruneWeights(const Eigen::MatrixXd& weights, int max_influences) {
  const int n = static_cast<int>(weights.rows());
  const int k = static_cast<int>(weights.cols());
  const int m = std::max(1, max_influences);
  SparseSkin skin;
  skin.joints = Eigen::MatrixXi::Zero(n, m);
  skin.weights = Eigen::MatrixXd::Zero(n, m);
  std::vector<int> order(k);
  for (int i = 0; i < n; ++i) {
    std::iota(order.begin(), order.end(), 0);
    // Stable: equal weights keep ascending joint order (deterministic ties).
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return weights(i, a) > weights(i, b); });
    double sum = 0.0;
    const int kept = std::min(m, k);
    for (int s = 0; s < kept; ++s) {
      double w = std::max(0.0, weights(i, order[s]));
      if (w <= 0.0) break;  // unused slots stay (joint 0, weight 0)
      skin.joints(i, s) = order[s];
      skin.weights(i, s) = w;
      sum += w;
    }
    if (sum > 0.0) {
      skin.weights.row(i) /= sum;
    } else {  // a vertex with no weight follows the root rather than vanishing
      skin.joints(i, 0) = 0;
      skin.weights(i, 0) = 1.0;
    }
  }
  return skin;
}

Eigen::MatrixXd denseWeights(const SparseSkin& skin, int num_joints) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(skin.joints.rows(), num_joints);
  for (int i = 0; i < skin.joints.rows(); ++i)
    for (int s = 0; s < skin.joints.cols(); ++s) dense(i, skin.joints(i, s)) += skin.weights(i, s);
  return dense;
}

}  // namespace smpl
