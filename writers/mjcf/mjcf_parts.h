// The physical body parts of the MJCF writer (mjcf_writer.h): per joint a
// mass share of the closed rest mesh, an inertia and a collision capsule, all
// from the mesh and its skin weights. Model axes (Y up, metres), world frame
// at the rest pose; the writer turns them Z up and into each body's frame.
//
// Volume: V = sum over triangles of v0 . (v1 x v2) / 6, the signed volume of
// the tetrahedra (origin, triangle) (divergence theorem; exact for a closed,
// outward-oriented surface, whatever the origin). A mesh with V <= 0 is an
// error (masses need a closed mesh).
//
// Parts: triangle t belongs to the joint with the largest summed skin weight
// of its three vertices (ties: the lower joint index). A part's share weight
// w_k is the signed volume of the cones from its centroid c_k (the mean of its
// triangles' vertices) over its triangles, floored at the volume of a 1 cm
// sphere (a part's surface is open where it meets its neighbours, so the cone
// is an estimate, and a part with no triangles gets the floor). The volumes
// are V * w_k / sum(w): positive, and they sum to V (to rounding).
//
// Inertia: the solid ellipsoid whose surface has the part's vertex covariance
// S (about c_k): solid second moments C = 3/5 S (a sphere's surface has
// r^2/3 per axis, its solid r^2/5), plus (5 mm)^2 on the diagonal so that a
// flat part stays positive definite; inertia about c_k per unit mass is
// tr(C) I - C (its eigenvalues obey the triangle inequality: l1 + l2 - l3 =
// 2 c3 > 0). A part with no triangles: a 1 cm solid sphere at the joint.
//
// Capsule: the vertices whose largest skin weight is joint k's (argmax of
// the row, ties the lower index; one per model vertex, seams merged by
// source_vertex), at least 3: centre c, axis a = the covariance's principal
// eigenvector, t_i = (v_i - c) . a, radius r = the median distance of the
// vertices from the axis line (at least 1 mm); the segment is [min t + r,
// max t - r] along a (the caps end at the extreme vertices); shorter than
// 0.1 mm: a sphere of radius r at the middle. Fewer than 3 vertices: no geom.
//
// Hull points (--mjcf-geoms mesh): the same dominated vertices, kept when
// they span a solid: at least 4, and a thickness (the square root of the
// covariance's smallest eigenvalue) of at least 1 mm; MuJoCo takes the
// convex hull of a mesh given by vertices alone. Otherwise empty (the
// writer falls back to the capsule: a flat or tiny hull is no collision
// shape, and MuJoCo's hull of coplanar points fails to load).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

struct MjcfGeom {
  enum class Kind { None, Capsule, Sphere } kind = Kind::None;
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // capsule ends; a sphere's centre is `from`
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  double radius = 0.0;  // metres
  // The dominated vertices (world, model axes) when they span a solid, else
  // empty: a convex hull mesh's points (--mjcf-geoms mesh).
  std::vector<Eigen::Vector3d> hull;
};

struct MjcfPart {
  double volume = 0.0;                               // m^3, > 0
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // centre of mass (world, model axes)
  Eigen::Matrix3d inertia_per_kg = Eigen::Matrix3d::Identity();  // about `center`, m^2
  MjcfGeom geom;
};

struct MjcfParts {
  double mesh_volume = 0.0;     // V, m^3
  std::vector<MjcfPart> parts;  // one per skeleton joint
};

// The parts of `asset`'s rest mesh, one per skeleton joint (K). Errors: no
// triangles, V <= 0 or not finite ("MJCF writer: ...").
Result<MjcfParts> mjcfParts(const Asset& asset);

}  // namespace smpl
