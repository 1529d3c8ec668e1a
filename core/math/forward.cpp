#include "core/math/forward.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "core/math/rotation.h"

namespace smpl {

Eigen::Matrix3d rodrigues(const Eigen::Vector3d& axis_angle) {
  const double angle = axis_angle.norm();
  if (angle < 1e-12) {
    // First-order expansion keeps tiny rotations exact to double precision.
    Eigen::Matrix3d k;
    k << 0, -axis_angle.z(), axis_angle.y(), axis_angle.z(), 0, -axis_angle.x(), -axis_angle.y(),
        axis_angle.x(), 0;
    return Eigen::Matrix3d::Identity() + k;
  }
  return axisAngleMatrix(angle, axis_angle / angle);
}

Rotations rotationsFromAxisAngle(const Eigen::VectorXd& axis_angle) {
  Rotations rotations(axis_angle.size() / 3);
  for (size_t k = 0; k < rotations.size(); ++k)
    rotations[k] = rodrigues(axis_angle.segment<3>(3 * k));
  return rotations;
}

Eigen::VectorXd poseFeatures(const Rotations& rotations) {
  const int k = static_cast<int>(rotations.size());
  Eigen::VectorXd f(9 * std::max(0, k - 1));
  for (int j = 1; j < k; ++j)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        f[9 * (j - 1) + 3 * r + c] = rotations[j](r, c) - (r == c ? 1.0 : 0.0);
  return f;
}

namespace {

Status checkLength(const char* what, Eigen::Index given, Eigen::Index available) {
  if (given > available)
    return makeError(std::string(what) + ": " + std::to_string(given) +
                     " values given; the model has " + std::to_string(available));
  return Status();
}

// dirs (3N x C) * coeffs, zero-padding coeffs to C; reshaped N x 3.
Eigen::MatrixXd blend(const Eigen::MatrixXd& dirs, const Eigen::VectorXd& coeffs) {
  const Eigen::Index n = dirs.rows() / 3;
  Eigen::VectorXd flat = dirs.leftCols(coeffs.size()) * coeffs;
  return Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(flat.data(), n, 3);
}

}  // namespace

Result<ShapedBody> shapeBody(const BodyModel& model, const Eigen::VectorXd& betas,
                             const Eigen::VectorXd& expression) {
  if (Status s = checkLength("betas", betas.size(), model.numBetas()); !s) return s.error();
  if (Status s = checkLength("expression", expression.size(), model.numExpressions()); !s)
    return s.error();
  ShapedBody body;
  body.v_shaped = model.v_template;
  if (betas.size() > 0) body.v_shaped += blend(model.shapedirs, betas);
  if (expression.size() > 0) body.v_shaped += blend(model.exprdirs, expression);
  body.joints = model.j_regressor * body.v_shaped;
  return body;
}

namespace {

// G_k = G_p(k) [R_k | J_k - J_p(k)] (docs/file-contract.md), root translated by J_0.
std::vector<Eigen::Matrix4d> worldTransforms(const BodyModel& model, const Rotations& rotations,
                                             const Eigen::MatrixXd& joints) {
  const int k = model.numJoints();
  std::vector<Eigen::Matrix4d> world(k);
  for (int j = 0; j < k; ++j) {
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    local.topLeftCorner<3, 3>() = rotations[j];
    const int p = model.parents[j];
    Eigen::Vector3d offset = joints.row(j).transpose();
    if (p >= 0) offset -= joints.row(p).transpose();
    local.topRightCorner<3, 1>() = offset;
    world[j] = p >= 0 ? Eigen::Matrix4d(world[p] * local) : local;
  }
  return world;
}

// v' = sum_k w_ik A_k v, as one (N x K)(K x 12) product of the top 3x4 rows.
Eigen::MatrixXd skin(const Eigen::MatrixXd& weights, const std::vector<Eigen::Matrix4d>& world,
                     const Eigen::MatrixXd& joints, const Eigen::MatrixXd& v_posed) {
  const Eigen::Index k = static_cast<Eigen::Index>(world.size());
  Eigen::Matrix<double, Eigen::Dynamic, 12> a(k, 12);
  for (Eigen::Index j = 0; j < k; ++j) {
    Eigen::Matrix4d remove_rest = Eigen::Matrix4d::Identity();
    remove_rest.topRightCorner<3, 1>() = -joints.row(j).transpose();
    Eigen::Matrix4d aj = world[j] * remove_rest;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) a(j, 4 * r + c) = aj(r, c);
  }
  Eigen::Matrix<double, Eigen::Dynamic, 12> blended = weights * a;
  Eigen::MatrixXd out(v_posed.rows(), 3);
  for (Eigen::Index i = 0; i < v_posed.rows(); ++i)
    for (int r = 0; r < 3; ++r)
      out(i, r) = blended(i, 4 * r) * v_posed(i, 0) + blended(i, 4 * r + 1) * v_posed(i, 1) +
                  blended(i, 4 * r + 2) * v_posed(i, 2) + blended(i, 4 * r + 3);
  return out;
}

Status checkInput(const BodyModel& model, const ForwardInput& input) {
  if (static_cast<int>(input.rotations.size()) != model.numJoints())
    return makeError("pose: " + std::to_string(input.rotations.size()) +
                     " rotations given; the model has " + std::to_string(model.numJoints()) +
                     " joints");
  if (input.weights &&
      (input.weights->rows() != model.numVertices() || input.weights->cols() != model.numJoints()))
    return makeError("skin weights override has the wrong shape");
  return Status();
}

}  // namespace

Result<ForwardResult> forward(const BodyModel& model, const ForwardInput& input) {
  if (Status s = checkInput(model, input); !s) return s.error();
  Result<ShapedBody> shaped = shapeBody(model, input.betas, input.expression);
  if (!shaped) return shaped.error();
  ForwardResult out;
  out.v_shaped = std::move(shaped->v_shaped);
  out.rest_joints = std::move(shaped->joints);
  out.pose_features = poseFeatures(input.rotations);
  Eigen::MatrixXd v_posed = out.v_shaped;
  if (input.pose_correctives && out.pose_features.size() > 0)
    v_posed += blend(model.posedirs, out.pose_features);
  out.world = worldTransforms(model, input.rotations, out.rest_joints);
  const Eigen::MatrixXd& weights = input.weights ? *input.weights : model.weights;
  out.vertices = skin(weights, out.world, out.rest_joints, v_posed);
  out.vertices.rowwise() += input.translation.transpose();
  out.joints.resize(model.numJoints(), 3);
  for (int j = 0; j < model.numJoints(); ++j)
    out.joints.row(j) =
        out.world[j].topRightCorner<3, 1>().transpose() + input.translation.transpose();
  return out;
}

}  // namespace smpl
