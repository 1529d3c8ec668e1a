// Assembles the built-in demo body from its stages (demo_body_internal.h).
#include "core/demo/demo_body.h"

#include "core/demo/demo_body_internal.h"
#include "core/joint_names.h"
#include "core/math/eigen_blocking.h"

namespace smpl {
namespace demo {
namespace {

// Marching-cubes cell: 2.2 cm gives about 4600 vertices, enough for a smooth
// silhouette with hands and feet, small enough to build in well under 1 s.
constexpr double kCell = 0.022;
// Training poses for the corrective fit; fixed seed, so the fit is fixed.
constexpr int kFitPoses = 240;
constexpr uint64_t kFitSeed = 0x5EED0DE3017ull;

}  // namespace

BodyModel buildDemoBody() {
  useFixedEigenBlocking();  // its fits are products too
  const Rig& r = rig();
  Mesh mesh = polygonise(r, kCell);
  BodyModel m;
  m.kind = ModelKind::Smpl;
  m.name = "builtin";
  m.joint_names = canonicalJointNames(ModelKind::Smpl);
  m.parents = r.parents;
  m.v_template = std::move(mesh.vertices);
  m.faces = std::move(mesh.faces);
  m.weights = skinWeights(r, m.v_template);
  m.j_regressor = jointRegressor(r, m.v_template);
  m.shapedirs = shapeDirections(r, m.v_template, m.weights);
  m.exprdirs = Eigen::MatrixXd(3 * m.numVertices(), 0);
  m.posedirs = fitPosedirs(m, kFitPoses, kFitSeed);
  return m;
}

}  // namespace demo

const BodyModel& demoBody() {
  static const BodyModel body = demo::buildDemoBody();
  return body;
}

}  // namespace smpl
