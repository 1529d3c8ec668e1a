// The reference forward pass of docs/file-contract.md, in double precision:
//   v_shaped = T + S beta (+ E psi)      J = J_regressor v_shaped
//   f = [vec(R_k - I)], k >= 1           v_posed = v_shaped + P f
//   G_k = G_p(k) [R_k | J_k - J_p(k)]    A_k = G_k [I | -J_k]
//   v' = sum_k w_ik A_k v_posed_i (+ translation)
// This is the ground truth that exported assets are compared against.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/body_model.h"
#include "core/result.h"

namespace smpl {

using Rotations = std::vector<Eigen::Matrix3d>;  // one local rotation per joint

// Rodrigues: axis-angle (radians) -> rotation matrix; exact at zero.
Eigen::Matrix3d rodrigues(const Eigen::Vector3d& axis_angle);
// 3K axis-angle values -> K rotations.
Rotations rotationsFromAxisAngle(const Eigen::VectorXd& axis_angle);

// f, 9(K-1) values, row-major vec(R_k - I) for k = 1..K-1.
Eigen::VectorXd poseFeatures(const Rotations& rotations);

// Shape only: the subject's rest mesh and rest joints.
struct ShapedBody {
  Eigen::MatrixXd v_shaped;  // N x 3
  Eigen::MatrixXd joints;    // K x 3 rest joints J(beta)
};

// `betas` may be shorter than the model's (zero-padded), never longer;
// same for `expression`.
Result<ShapedBody> shapeBody(const BodyModel& model, const Eigen::VectorXd& betas,
                             const Eigen::VectorXd& expression = Eigen::VectorXd());

struct ForwardInput {
  Eigen::VectorXd betas;
  Eigen::VectorXd expression;
  Rotations rotations;  // K local rotations (model axes)
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  const Eigen::MatrixXd* weights = nullptr;  // N x K override (e.g. pruned); null = model's
  bool pose_correctives = true;              // false: skip P f (LBS only)
};

struct ForwardResult {
  Eigen::MatrixXd vertices;            // N x 3 posed
  Eigen::MatrixXd v_shaped;            // N x 3
  Eigen::MatrixXd joints;              // K x 3 posed joint positions
  Eigen::MatrixXd rest_joints;         // K x 3
  Eigen::VectorXd pose_features;       // 9(K-1)
  std::vector<Eigen::Matrix4d> world;  // G_k
};

Result<ForwardResult> forward(const BodyModel& model, const ForwardInput& input);

}  // namespace smpl
