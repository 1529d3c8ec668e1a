// Private pieces of the built-in demo body (core/demo_body.h), one stage per
// file, exposed here so the tests can build the body without the memoised
// copy and check each stage against independent math.
//
//   demo_shape.cpp        rest joints and 24 body parts (round cones); the body
//                         is the smooth union of the parts, an implicit surface
//   demo_mesh.cpp         marching cubes on that field -> one closed manifold
//   demo_skin.cpp         skin weights from part distances; joint regressor
//   demo_shapedirs.cpp    10 shape directions (height, girth, ...)
//   demo_correctives.cpp  dual-quaternion target and the posedirs fit
//   demo_body.cpp         assembly and memoisation
//
// Hot loops use the small V3 below instead of Eigen so that Debug and
// sanitizer builds (where the tests run) stay fast.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/body_model.h"

namespace smpl {
namespace demo {

constexpr int kNumJoints = 24;

struct V3 {
  double x = 0, y = 0, z = 0;
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length(V3 a) { return std::sqrt(dot(a, a)); }
inline V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// One body part: a round cone (sphere-swept segment a-b, radius ra..rb),
// evaluated in a space squashed per world axis so that hands and feet are
// flat and the torso is deeper than wide. Part k is moved by joint k.
struct Part {
  V3 a, b;
  double ra = 0, rb = 0;
  V3 squash{1, 1, 1};
  // Bounding sphere (centre, radius), for skipping far parts.
  V3 centre;
  double reach = 0;
};

struct Rig {
  std::vector<V3> joints;   // 24 rest joints, metres, +Y up, facing +Z, left = +X
  std::vector<Part> parts;  // 24 parts, parts[k] moved by joint k
  std::vector<int> parents;
};

const Rig& rig();

// Approximate signed distance to one part (negative inside).
double partDistance(const Part& part, V3 p);
// The body: each part blended smoothly with its parent's part; < 0 inside.
double bodyField(const Rig& rig, V3 p);
// Closest point on a part's axis and its parameter t in [0, 1].
V3 closestOnAxis(const Part& part, V3 p, double* t);

struct Mesh {
  Eigen::MatrixXd vertices;  // N x 3
  Eigen::MatrixXi faces;     // F x 3, counter-clockwise seen from outside
};

// Marching cubes with cell size `cell` (metres), largest component only,
// vertices relaxed along the surface and projected back onto it.
Mesh polygonise(const Rig& rig, double cell);

// N x 24, rows sum to 1: soft minimum over the parts' distances.
Eigen::MatrixXd skinWeights(const Rig& rig, const Eigen::MatrixXd& vertices);
// K x N, rows sum to 1, non-negative, each row's weighted mean of the rest
// vertices equal to the rig's joint.
Eigen::SparseMatrix<double, Eigen::RowMajor> jointRegressor(const Rig& rig,
                                                            const Eigen::MatrixXd& vertices);
// 3N x 10 shape directions (see demo_shapedirs.cpp for the meaning of each).
Eigen::MatrixXd shapeDirections(const Rig& rig, const Eigen::MatrixXd& vertices,
                                const Eigen::MatrixXd& weights);

// Deterministic plausible poses: 3K axis-angle values, per-joint ranges.
std::vector<Eigen::VectorXd> sampleDemoPoses(int count, uint64_t seed);
// The target deformer the correctives imitate: dual-quaternion skinning of
// the model's rest mesh (betas 0, no correctives) with local rotations.
Eigen::MatrixXd dualQuaternionSkin(const BodyModel& model,
                                   const std::vector<Eigen::Matrix3d>& rotations);
// 3N x 207 posedirs: per vertex, ridge least squares of the rest-space offset
// that turns LBS into the target, on the features of the joints skinning it.
Eigen::MatrixXd fitPosedirs(const BodyModel& model, int num_poses, uint64_t seed);

// The whole body, built from scratch (demoBody() memoises this).
BodyModel buildDemoBody();

}  // namespace demo
}  // namespace smpl
