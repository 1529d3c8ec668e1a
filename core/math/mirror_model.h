// The mirror image of a body model across the x = 0 plane (S = diag(-1, 1, 1)),
// as the MANO authors' left hand relates to their right hand, and as HaMeR
// shows a left hand (geopavlakos/hamer demo.py: the right-hand MANO output
// with x negated, faces re-wound). For every pose,
//   mirrored(S R_k S) = S * model(R_k)      (vertices and joints)
// because, with x negated:
//   v_template, shapedirs, exprdirs   x rows negated (J_regressor, weights and
//                                     the kintree are unchanged: joints are
//                                     linear in the vertices)
//   posedirs column (k, r, c)         x rows negated, times s_r s_c: the
//                                     mirrored pose's feature S(R - I)S has
//                                     entry (r, c) = s_r s_c (R - I)_rc
//   faces                             winding flipped (a, b, c) -> (a, c, b),
//                                     so normals still point outward
//   hands PCA (45 = 15 axis-angle)    axis-angle (x, y, z) -> (x, -y, -z)
// UVs are kept (the texture is mirrored with the body).
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/body_model.h"
#include "core/math/forward.h"

namespace smpl {

// The mirrored model, named "<name> (mirrored)".
BodyModel mirrorModel(const BodyModel& model);

// S R S: a rotation of the mirrored body (axis-angle (x, y, z) -> (x, -y, -z)).
Eigen::Matrix3d mirrorRotation(const Eigen::Matrix3d& r);

// "left" when the model's file name says so (MANO_LEFT.pkl, mano_left.npz),
// else "right": the authors' MANO files are named by side. Only meaningful for
// MANO models.
std::string manoSide(const BodyModel& model);

}  // namespace smpl
