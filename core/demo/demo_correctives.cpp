// Pose correctives of the demo body, fitted in code. SMPL learnt its
// posedirs from scans; we have no scans, so the target is a better skinning
// method than LBS: dual-quaternion skinning (DQS), which keeps volume at
// bends and twists where LBS collapses ("candy wrapper"). For sampled poses
// the offset that turns LBS into DQS, taken back to the rest pose,
//   delta_i = (sum_k w_ik R_k)^-1 (v_DQS - v_LBS),
// is regressed on the pose features f of the joints that skin vertex i
// (ridge least squares). Vertices sharing one set of joints share the normal
// matrix, so the whole fit costs one small factorisation per set.
#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <map>

#include "core/demo/demo_body_internal.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"

namespace smpl {
namespace demo {
namespace {

// Per-joint range of each axis-angle component (radians): wide at hips,
// knees, shoulders and elbows, narrow along the spine and at the hands.
const double kPoseRange[kNumJoints] = {0.0, 0.7, 0.7, 0.3, 0.9, 0.9, 0.3, 0.4, 0.4, 0.3, 0.3, 0.3,
                                       0.4, 0.3, 0.3, 0.4, 0.8, 0.8, 0.9, 0.9, 0.5, 0.5, 0.3, 0.3};

// A_k = G_k [I | -J_k] as rotation, translation and the unit dual quaternion.
struct Bone {
  double r[9], t[3];
  double q[4], d[4];  // real part (w, x, y, z), dual part
};

std::vector<Bone> skinningBones(const BodyModel& model, const Eigen::MatrixXd& joints,
                                const Rotations& rotations) {
  const int nj = model.numJoints();
  std::vector<Eigen::Matrix3d> rot(nj);
  std::vector<Eigen::Vector3d> pos(nj);
  std::vector<Bone> bones(nj);
  for (int k = 0; k < nj; ++k) {
    const int p = model.parents[k];
    const Eigen::Vector3d j = joints.row(k).transpose();
    rot[k] = p < 0 ? rotations[k] : Eigen::Matrix3d(rot[p] * rotations[k]);
    pos[k] = p < 0 ? j : Eigen::Vector3d(pos[p] + rot[p] * (j - joints.row(p).transpose()));
    const Eigen::Vector3d t = pos[k] - rot[k] * j;
    const Eigen::Quaterniond q(rot[k]);
    Bone& b = bones[k];
    for (int e = 0; e < 9; ++e) b.r[e] = rot[k](e / 3, e % 3);
    for (int c = 0; c < 3; ++c) b.t[c] = t[c];
    b.q[0] = q.w(), b.q[1] = q.x(), b.q[2] = q.y(), b.q[3] = q.z();
    // d = 1/2 (0, t) q
    const Eigen::Vector3d v(q.x(), q.y(), q.z());
    const Eigen::Vector3d dv = 0.5 * (q.w() * t + t.cross(v));
    b.d[0] = -0.5 * t.dot(v), b.d[1] = dv.x(), b.d[2] = dv.y(), b.d[3] = dv.z();
  }
  return bones;
}

struct Influence {
  int joint;
  double weight;
};

std::vector<std::vector<Influence>> influences(const Eigen::MatrixXd& weights) {
  std::vector<std::vector<Influence>> inf(weights.rows());
  for (int i = 0; i < weights.rows(); ++i)
    for (int k = 0; k < weights.cols(); ++k)
      if (weights(i, k) > 0) inf[i].push_back({k, weights(i, k)});
  return inf;
}

V3 lbs(const std::vector<Bone>& bones, const std::vector<Influence>& inf, V3 p, double* m) {
  std::fill(m, m + 9, 0.0);
  V3 t;
  for (const Influence& in : inf) {
    const Bone& b = bones[in.joint];
    for (int e = 0; e < 9; ++e) m[e] += in.weight * b.r[e];
    t = t + V3{b.t[0], b.t[1], b.t[2]} * in.weight;
  }
  return V3{m[0] * p.x + m[1] * p.y + m[2] * p.z, m[3] * p.x + m[4] * p.y + m[5] * p.z,
            m[6] * p.x + m[7] * p.y + m[8] * p.z} +
         t;
}

V3 dqs(const std::vector<Bone>& bones, const std::vector<Influence>& inf, V3 p) {
  const Influence* pivot = &inf[0];
  for (const Influence& in : inf)
    if (in.weight > pivot->weight) pivot = &in;
  const double* qp = bones[pivot->joint].q;
  double b0[4] = {0, 0, 0, 0}, be[4] = {0, 0, 0, 0};
  for (const Influence& in : inf) {
    const Bone& b = bones[in.joint];
    // Shortest path: flip quaternions on the other hemisphere from the pivot.
    const double s = (b.q[0] * qp[0] + b.q[1] * qp[1] + b.q[2] * qp[2] + b.q[3] * qp[3]) < 0
                         ? -in.weight
                         : in.weight;
    for (int c = 0; c < 4; ++c) b0[c] += s * b.q[c], be[c] += s * b.d[c];
  }
  const double norm = std::sqrt(b0[0] * b0[0] + b0[1] * b0[1] + b0[2] * b0[2] + b0[3] * b0[3]);
  const double w0 = b0[0] / norm, we = be[0] / norm;
  const V3 v0{b0[1] / norm, b0[2] / norm, b0[3] / norm},
      ve{be[1] / norm, be[2] / norm, be[3] / norm};
  const V3 rotated = p + cross(v0, p) * (2 * w0) + cross(v0, cross(v0, p)) * 2;
  return rotated + (ve * w0 - v0 * we + cross(v0, ve)) * 2;
}

// Solves m x = v for a 3x3 row-major m by Cramer's rule (the blended LBS
// matrix is close to a rotation, never singular for these weights and poses);
// written out because it runs once per vertex and pose, also in Debug builds.
V3 solve3(const double* m, V3 v) {
  const V3 c0{m[0], m[3], m[6]}, c1{m[1], m[4], m[7]}, c2{m[2], m[5], m[8]};
  const double det = dot(c0, cross(c1, c2));
  return V3{dot(v, cross(c1, c2)), dot(c0, cross(v, c2)), dot(c0, cross(c1, v))} * (1.0 / det);
}

}  // namespace

std::vector<Eigen::VectorXd> sampleDemoPoses(int count, uint64_t seed) {
  uint64_t state = seed;
  std::vector<Eigen::VectorXd> poses(count, Eigen::VectorXd(3 * kNumJoints));
  for (Eigen::VectorXd& pose : poses)
    for (int i = 0; i < 3 * kNumJoints; ++i)
      pose[i] = (2.0 * uniform01(&state) - 1.0) * kPoseRange[i / 3];
  return poses;
}

Eigen::MatrixXd dualQuaternionSkin(const BodyModel& model,
                                   const std::vector<Eigen::Matrix3d>& rotations) {
  const Eigen::MatrixXd joints = model.j_regressor * model.v_template;
  const std::vector<Bone> bones = skinningBones(model, joints, rotations);
  const auto inf = influences(model.weights);
  Eigen::MatrixXd out(model.numVertices(), 3);
  for (int i = 0; i < model.numVertices(); ++i) {
    const V3 v = dqs(bones, inf[i],
                     {model.v_template(i, 0), model.v_template(i, 1), model.v_template(i, 2)});
    out.row(i) << v.x, v.y, v.z;
  }
  return out;
}

namespace {

// Vertices grouped by the joints (k >= 1, weight > 1%) whose features they use.
struct FeatureGroups {
  std::vector<std::vector<int>> joints;  // per group, ascending
  std::vector<int> group_of;             // per vertex, -1: rigid (one influence)
};

FeatureGroups groupVertices(const std::vector<std::vector<Influence>>& inf) {
  FeatureGroups g;
  std::map<std::vector<int>, int> index;
  g.group_of.assign(inf.size(), -1);
  for (size_t i = 0; i < inf.size(); ++i) {
    if (inf[i].size() < 2) continue;  // LBS equals DQS for a single bone
    std::vector<int> set;
    for (const Influence& in : inf[i])
      if (in.joint > 0 && in.weight > 0.01) set.push_back(in.joint);
    if (set.empty()) continue;
    auto it = index.emplace(set, static_cast<int>(g.joints.size())).first;
    if (it->second == static_cast<int>(g.joints.size())) g.joints.push_back(set);
    g.group_of[i] = it->second;
  }
  return g;
}

}  // namespace

Eigen::MatrixXd fitPosedirs(const BodyModel& model, int num_poses, uint64_t seed) {
  const int n = model.numVertices(), nf = 9 * (model.numJoints() - 1);
  const Eigen::MatrixXd joints = model.j_regressor * model.v_template;
  const auto inf = influences(model.weights);
  const FeatureGroups groups = groupVertices(inf);
  // Normal equations: one Gram matrix of all features, X^T Y per vertex.
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(nf, nf);
  std::vector<std::vector<double>> xty(n);
  for (int i = 0; i < n; ++i)
    if (groups.group_of[i] >= 0) xty[i].assign(27 * groups.joints[groups.group_of[i]].size(), 0.0);
  for (const Eigen::VectorXd& pose : sampleDemoPoses(num_poses, seed)) {
    const Rotations rot = rotationsFromAxisAngle(pose);
    const Eigen::VectorXd f = poseFeatures(rot);
    for (int c = 0; c < nf; ++c) {  // upper triangle, column-major, plain loops
      double* col = gram.data() + static_cast<size_t>(c) * nf;
      for (int r = 0; r <= c; ++r) col[r] += f[r] * f[c];
    }
    const std::vector<Bone> bones = skinningBones(model, joints, rot);
    for (int i = 0; i < n; ++i) {
      if (groups.group_of[i] < 0) continue;
      const V3 p{model.v_template(i, 0), model.v_template(i, 1), model.v_template(i, 2)};
      double m[9];
      const V3 v_lbs = lbs(bones, inf[i], p, m);
      const V3 delta = solve3(m, dqs(bones, inf[i], p) - v_lbs);
      const std::vector<int>& set = groups.joints[groups.group_of[i]];
      double* acc = xty[i].data();
      for (int k : set)
        for (int e = 0; e < 9; ++e, acc += 3) {
          const double fe = f[9 * (k - 1) + e];
          acc[0] += fe * delta.x, acc[1] += fe * delta.y, acc[2] += fe * delta.z;
        }
    }
  }
  gram = gram.selfadjointView<Eigen::Upper>();
  Eigen::MatrixXd posedirs = Eigen::MatrixXd::Zero(3 * n, nf);
  std::vector<std::vector<int>> members(groups.joints.size());
  for (int i = 0; i < n; ++i)
    if (groups.group_of[i] >= 0) members[groups.group_of[i]].push_back(i);
  for (size_t g = 0; g < groups.joints.size(); ++g) {
    std::vector<int> cols;
    for (int k : groups.joints[g])
      for (int e = 0; e < 9; ++e) cols.push_back(9 * (k - 1) + e);
    const int m = static_cast<int>(cols.size());
    Eigen::MatrixXd a(m, m);
    for (int r = 0; r < m; ++r)
      for (int c = 0; c < m; ++c) a(r, c) = gram(cols[r], cols[c]);
    // Ridge: features that barely vary (or are collinear) stay near zero.
    a.diagonal().array() += 1e-3 * a.trace() / m + 1e-9;
    const Eigen::LLT<Eigen::MatrixXd> llt(a);
    for (int i : members[g]) {
      const Eigen::MatrixXd p =
          llt.solve(Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
              xty[i].data(), m, 3));
      for (int r = 0; r < m; ++r)
        for (int c = 0; c < 3; ++c) posedirs(3 * i + c, cols[r]) = p(r, c);
    }
  }
  return posedirs;
}

}  // namespace demo
}  // namespace smpl
