#include "exporter/corrective_basis.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <string>

#include "core/math/forward.h"
#include "core/math/pose_sampler.h"

namespace smpl {
namespace {

// Flip each column of B (and the matching row of C) so that its
// largest-magnitude entry is positive; the first such entry wins ties.
void fixSigns(Eigen::MatrixXd* basis) {
  for (Eigen::Index k = 0; k < basis->cols(); ++k) {
    Eigen::Index at = 0;
    basis->col(k).cwiseAbs().maxCoeff(&at);
    if ((*basis)(at, k) < 0) basis->col(k) *= -1.0;
  }
}

// Number of components above the numerical noise of the Gram matrix.
int numericalRank(const Eigen::VectorXd& descending) {
  if (descending.size() == 0 || descending(0) <= 0) return 0;
  int rank = 0;
  while (rank < descending.size() && descending(rank) > 1e-14 * descending(0)) ++rank;
  return rank;
}

// max over rotations R of <M, R>_F = s1 + s2 + sign(det M) s3 (Procrustes).
double maxInnerWithRotation(const Eigen::Matrix3d& m) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m);
  const Eigen::Vector3d s = svd.singularValues();
  return s(0) + s(1) + (m.determinant() < 0 ? -s(2) : s(2));
}

}  // namespace

Result<CorrectiveBasisFit> fitCorrectiveBasis(const Eigen::MatrixXd& posedirs, int k) {
  const int p = static_cast<int>(posedirs.cols());
  if (k < 1 || k > p)
    return makeError("--corrective-basis " + std::to_string(k) + ": expected 1.." +
                     std::to_string(p) + " (the model has " + std::to_string(p) +
                     " pose correctives)");
  if (posedirs.rows() < p)
    return makeError("--corrective-basis: posedirs has fewer rows (" +
                     std::to_string(posedirs.rows()) + ") than columns (" + std::to_string(p) +
                     ")");
  const Eigen::MatrixXd gram = posedirs.transpose() * posedirs;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
  if (eig.info() != Eigen::Success)
    return makeError("--corrective-basis: eigen-decomposition did not converge");
  // The solver sorts ascending: reverse to take the leading components.
  const Eigen::VectorXd variance = eig.eigenvalues().reverse();
  const Eigen::MatrixXd vectors = eig.eigenvectors().rowwise().reverse();
  k = std::min(k, numericalRank(variance));
  if (k == 0) return makeError("--corrective-basis: posedirs is zero (no corrective to keep)");
  // posedirs V_K spans the leading principal subspace; a Householder QR makes
  // its orthonormal basis exact (B = posedirs V Lambda^-1/2 loses
  // orthogonality in small components, where Lambda is only known to
  // eps * Lambda_max).
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(posedirs * vectors.leftCols(k));
  CorrectiveBasisFit fit;
  fit.basis = qr.householderQ() * Eigen::MatrixXd::Identity(posedirs.rows(), k);
  fixSigns(&fit.basis);
  fit.projection = fit.basis.transpose() * posedirs;
  fit.variance = variance.head(k);
  return fit;
}

void weightRange(const Eigen::MatrixXd& projection, Eigen::VectorXd* lo, Eigen::VectorXd* hi) {
  const Eigen::Index k = projection.rows(), joints = projection.cols() / 9;
  *lo = Eigen::VectorXd::Zero(k);
  *hi = Eigen::VectorXd::Zero(k);
  for (Eigen::Index c = 0; c < k; ++c)
    for (Eigen::Index j = 0; j < joints; ++j) {
      // (C f)_c = sum_j <M_j, R_j - I>, M_j[r][s] = C[c, 9j + 3r + s]; joints are independent.
      Eigen::Matrix3d m;
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) m(r, s) = projection(c, 9 * j + 3 * r + s);
      (*hi)(c) += maxInnerWithRotation(m) - m.trace();
      (*lo)(c) += -maxInnerWithRotation(-m) - m.trace();
    }
}

std::vector<BasisError> basisErrorReport(const BodyModel& model, const std::vector<int>& ks,
                                         int poses, uint64_t seed) {
  const int p = model.numPoseFeatures();
  Result<CorrectiveBasisFit> fit = fitCorrectiveBasis(model.posedirs, p);
  std::vector<BasisError> rows;
  if (!fit) return rows;
  // Householder QR is column-sequential: the first K columns of the full
  // basis are the K-component basis, so one fit serves every K.
  const Eigen::MatrixXd& b = fit->basis;
  const int rank = static_cast<int>(b.cols());
  const std::vector<Eigen::VectorXd> pose_set = samplePoses(model.numJoints(), poses, seed);
  for (int k : ks) {
    BasisError e;
    e.components = std::min(k, p);
    const int used = std::min(e.components, rank);
    double sum = 0.0;
    for (const Eigen::VectorXd& pose : pose_set) {
      const Eigen::VectorXd d = model.posedirs * poseFeatures(rotationsFromAxisAngle(pose));
      const Eigen::VectorXd residual = d - b.leftCols(used) * (b.leftCols(used).transpose() * d);
      for (Eigen::Index i = 0; i + 2 < residual.size(); i += 3) {
        const double err = residual.segment<3>(i).norm();
        e.max_error = std::max(e.max_error, err);
        sum += err;
      }
    }
    const double count = double(pose_set.size()) * double(model.posedirs.rows() / 3);
    e.mean_error = count > 0 ? sum / count : 0.0;
    rows.push_back(e);
  }
  return rows;
}

}  // namespace smpl
