// The range checks of a loaded motion (bounds in core/models/validate_inputs.h).
#include "core/motions/validate_motion.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <cstdio>

#include "core/joint_names.h"
#include "core/models/validate_inputs.h"

namespace smpl {
namespace {

// Nearest rotation to `r`, or an error naming frame and joint.
Status checkRotation(Eigen::Matrix3d* r, const Motion& m, size_t frame, size_t joint,
                     const std::string& path) {
  const double error = (r->transpose() * *r - Eigen::Matrix3d::Identity()).norm();
  const double det = r->determinant();
  if (error <= kRotationTolerance && det > 0) {
    if (error > 1e-12) {
      Eigen::JacobiSVD<Eigen::Matrix3d> svd(*r, Eigen::ComputeFullU | Eigen::ComputeFullV);
      *r = svd.matrixU() * svd.matrixV().transpose();
    }
    return Status();
  }
  const std::vector<std::string>& names = canonicalJointNames(m.layout);
  const std::string name = joint < names.size() ? " (" + names[joint] + ")" : "";
  return makeError(path + ": 'poses' frame " + std::to_string(frame) + " joint " +
                   std::to_string(joint) + name + " is not a rotation matrix: ||R^T R - I|| = " +
                   boundText(error) + ", det = " + boundText(det) +
                   "; expected orthonormal with det +1 within " + boundText(kRotationTolerance));
}

// The per-frame frame change (Motion::world_rotation/_translation): one per
// frame, rotations, translations within kMaxTranslation; expression finite.
Status checkFrameChange(Motion* m, const std::string& path) {
  const size_t t = m->frames.size();
  if (m->world_rotation.size() != m->world_translation.size() ||
      (!m->world_rotation.empty() && m->world_rotation.size() != t))
    return makeError(path + ": " + std::to_string(m->world_rotation.size()) +
                     " frame rotations and " + std::to_string(m->world_translation.size()) +
                     " translations for " + std::to_string(t) + " frames");
  for (size_t f = 0; f < m->world_rotation.size(); ++f) {
    Eigen::Matrix3d& r = m->world_rotation[f];
    const double error = (r.transpose() * r - Eigen::Matrix3d::Identity()).norm();
    if (!(error <= kRotationTolerance) || !(r.determinant() > 0))
      return makeError(path + ": the frame rotation of frame " + std::to_string(f) +
                       " is not a rotation matrix (||R^T R - I|| = " + boundText(error) + ")");
    if (error > 1e-12) {
      Eigen::JacobiSVD<Eigen::Matrix3d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
      r = svd.matrixU() * svd.matrixV().transpose();
    }
    for (int c = 0; c < 3; ++c)
      if (!(std::abs(m->world_translation[f][c]) <= kMaxTranslation))
        return makeError(path + ": the frame translation of frame " + std::to_string(f) + " is " +
                         boundText(m->world_translation[f][c]) +
                         " m; expected finite values within " + boundText(kMaxTranslation) + " m");
  }
  if (m->expression.rows() > 0 && static_cast<size_t>(m->expression.rows()) != t)
    return makeError(path + ": " + std::to_string(m->expression.rows()) +
                     " rows of expression coefficients for " + std::to_string(t) + " frames");
  for (Eigen::Index i = 0; i < m->expression.size(); ++i)
    if (!(std::abs(m->expression.data()[i]) <= kMaxCoefficient))
      return makeError(path + ": an expression coefficient is " +
                       boundText(m->expression.data()[i]) + "; expected finite values within " +
                       boundText(kMaxCoefficient));
  return Status();
}

}  // namespace

Status checkMotionValues(Motion* m, const std::string& path) {
  if (Status st = checkFrameRate(m->fps, path, "the frame rate"); !st) return st;
  if (Status st = checkCoefficients(m->betas, path, "'betas'"); !st) return st;
  for (size_t f = 0; f < m->translation.size(); ++f)
    for (int c = 0; c < 3; ++c)
      if (!(std::abs(m->translation[f][c]) <= kMaxTranslation))
        return makeError(path + ": 'trans' frame " + std::to_string(f) + " is " +
                         boundText(m->translation[f][c]) + " m; expected finite values within " +
                         boundText(kMaxTranslation) + " m");
  for (size_t f = 0; f < m->frames.size(); ++f)
    for (size_t j = 0; j < m->frames[f].size(); ++j)
      if (Status st = checkRotation(&m->frames[f][j], *m, f, j, path); !st) return st;
  return checkFrameChange(m, path);
}

}  // namespace smpl
