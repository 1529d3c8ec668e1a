// Skin weight pruning: keep the M largest influences per vertex, renormalise
// to sum 1 (docs/file-contract.md "Baking a subject"). Ties break toward the lower joint
// index so output is deterministic.
#pragma once

#include <Eigen/Core>

namespace smpl {

struct SparseSkin {
  Eigen::MatrixXi joints;   // N x M joint indices, sorted by descending weight
  Eigen::MatrixXd weights;  // N x M, rows sum to 1; unused slots are joint 0, weight 0
};

// M = max_influences; a precondition, not a user-facing check (the export
// request checks --max-influences once, request/check_request.h):
// M < 1 is taken as 1.
SparseSkin pruneWeights(const Eigen::MatrixXd& weights, int max_influences);

// Back to a dense N x K matrix (for the forward pass with pruned weights).
Eigen::MatrixXd denseWeights(const SparseSkin& skin, int num_joints);

}  // namespace smpl
