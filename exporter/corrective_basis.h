// A corrective budget: K principal components of posedirs replace its P
// columns as morph targets (`--corrective-basis K`).
//
//   posedirs (3N x P) ~= B C,  B (3N x K) orthonormal columns, C = B^T posedirs (K x P)
//   target k = B_k / scale_k,  weight_k = scale_k (C f)_k + offset_k
//
// B spans the K leading eigenvectors of the Gram matrix posedirs^T posedirs
// (P x P: cheap, where an SVD of the 3N x P matrix is not), orthonormalised
// by a QR so that B^T B = I to rounding even for small components, and
// B C = posedirs exactly at K = P. Signs are fixed (the largest-magnitude
// entry of each B column is positive) so the output is deterministic.
//
// Weights are bounded because rotations are: the range of (C f)_k over all
// rotations is exact, joint by joint (a Procrustes bound, see weightRange), so
//   Signed: scale_k = 1 / max(-lo_k, hi_k), offset 0 -> weights in [-1, 1]
//   Unit:   scale_k = 1 / (hi_k - lo_k), offset -lo_k scale_k -> weights in [0, 1]
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/body_model.h"
#include "core/result.h"

namespace smpl {

struct CorrectiveBasisFit {
  Eigen::MatrixXd basis;       // 3N x K, orthonormal columns (B)
  Eigen::MatrixXd projection;  // K x P, C = B^T posedirs
  Eigen::VectorXd variance;    // K eigenvalues of posedirs^T posedirs, descending
};

// K leading components; K in [1, P]. Components beyond the numerical rank of
// posedirs (eigenvalue <= 1e-14 of the largest) carry nothing: K is reduced
// to the rank (callers read basis.cols()).
Result<CorrectiveBasisFit> fitCorrectiveBasis(const Eigen::MatrixXd& posedirs, int k);

// Exact range [lo_k, hi_k] of (C f)_k over all joint rotations (f of docs/file-contract.md,
// 9 features per joint). lo <= 0 <= hi (f = 0 at the rest pose).
void weightRange(const Eigen::MatrixXd& projection, Eigen::VectorXd* lo, Eigen::VectorXd* hi);

// Error the truncation to K components adds over a pose set:
// e_i = |(posedirs - B_K C_K) f|_i per vertex, max and mean over vertices and poses.
struct BasisError {
  int components = 0;
  double max_error = 0.0;   // metres
  double mean_error = 0.0;  // metres
};

// One row per K in `ks` (values above P are clamped to P), poses from
// samplePoses(K joints, poses, seed).
std::vector<BasisError> basisErrorReport(const BodyModel& model, const std::vector<int>& ks,
                                         int poses, uint64_t seed);

}  // namespace smpl
