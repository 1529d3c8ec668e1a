#include "core/demo/demo_body.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <numeric>
#include <utility>

#include "core/demo/demo_body_internal.h"
#include "core/joint_names.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/models/model_loader.h"

namespace smpl {
namespace {

// SMPL's tree, typed here independently of the generator.
const int kSmplParents[24] = {-1, 0, 0, 0,  1,  2,  3,  4,  5,  6,  7,  8,
                              9,  9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21};

double signedVolume(const Eigen::MatrixXd& v, const Eigen::MatrixXi& f) {
  double vol = 0;
  for (int t = 0; t < f.rows(); ++t) {
    const Eigen::Vector3d a = v.row(f(t, 0)), b = v.row(f(t, 1)), c = v.row(f(t, 2));
    vol += a.dot(b.cross(c)) / 6.0;
  }
  return vol;
}

double height(const Eigen::MatrixXd& v) { return v.col(1).maxCoeff() - v.col(1).minCoeff(); }

TEST(DemoBody, StructureMatchesSmplAndValidates) {
  const BodyModel& m = demoBody();
  EXPECT_EQ(m.kind, ModelKind::Smpl);
  EXPECT_EQ(m.name, "builtin");
  ASSERT_EQ(m.numJoints(), 24);
  EXPECT_EQ(m.joint_names, canonicalJointNames(ModelKind::Smpl));
  EXPECT_EQ(m.joint_names[0], "pelvis");
  EXPECT_EQ(m.joint_names[23], "right_hand");
  for (int k = 0; k < 24; ++k) EXPECT_EQ(m.parents[k], kSmplParents[k]) << "joint " << k;
  EXPECT_GE(m.numVertices(), 3000);
  EXPECT_LE(m.numVertices(), 7000);
  EXPECT_EQ(m.numBetas(), 10);
  EXPECT_EQ(m.numPoseFeatures(), 207);
  EXPECT_EQ(m.posedirs.rows(), 3 * m.numVertices());
  EXPECT_EQ(m.numExpressions(), 0);
  EXPECT_EQ(m.hands_components_l.size(), 0);
  const Status s = validateModel(m, "builtin");
  EXPECT_TRUE(s.ok()) << s.message();
}

TEST(DemoBody, MeshIsOneClosedOrientedSphere) {
  const BodyModel& m = demoBody();
  const Eigen::MatrixXi& f = m.faces;
  // Closed and consistently oriented: each directed edge once, its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (int t = 0; t < f.rows(); ++t)
    for (int q = 0; q < 3; ++q) {
      ASSERT_NE(f(t, q), f(t, (q + 1) % 3)) << "degenerate face " << t;
      ++directed[{f(t, q), f(t, (q + 1) % 3)}];
    }
  int bad = 0;
  for (const auto& [e, count] : directed)
    bad += count != 1 || directed.count({e.second, e.first}) != 1;
  EXPECT_EQ(bad, 0);
  const long edges = static_cast<long>(directed.size()) / 2;
  EXPECT_EQ(m.numVertices() - edges + f.rows(), 2) << "Euler characteristic";
  // One connected piece, every vertex used.
  std::vector<int> parent(m.numVertices());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<bool> used(m.numVertices(), false);
  for (int t = 0; t < f.rows(); ++t)
    for (int q = 0; q < 3; ++q) {
      used[f(t, q)] = true;
      parent[root(f(t, q))] = root(f(t, 0));
    }
  int components = 0;
  for (int v = 0; v < m.numVertices(); ++v) components += root(v) == v;
  EXPECT_EQ(components, 1);
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
  // Counter-clockwise seen from outside: positive volume, about an adult's.
  const double vol = signedVolume(m.v_template, f);
  std::printf("[demo] %d vertices, %d faces, volume %.4f m^3\n", m.numVertices(),
              static_cast<int>(f.rows()), vol);
  EXPECT_GT(vol, 0.04);
  EXPECT_LT(vol, 0.12);
}

TEST(DemoBody, RestPoseIsAnAdultInTPose) {
  const BodyModel& m = demoBody();
  const Eigen::MatrixXd& v = m.v_template;
  EXPECT_GE(height(v), 1.5);
  EXPECT_LE(height(v), 1.9);
  EXPECT_NEAR(v.col(1).minCoeff(), 0.0, 0.01) << "feet on the floor";
  const Eigen::MatrixXd j = m.j_regressor * v;
  // Left is +X, arms straight out, head above the neck, facing +Z (toes forward).
  EXPECT_GT(j(22, 0), 0.6);
  EXPECT_LT(j(23, 0), -0.6);
  EXPECT_NEAR(j(20, 1), j(16, 1), 0.03) << "arm horizontal";
  EXPECT_GT(j(15, 1), j(12, 1));
  EXPECT_GT(j(10, 2), j(7, 2)) << "toes ahead of the ankle";
  EXPECT_GT(v.col(0).maxCoeff() - v.col(0).minCoeff(), 1.5) << "arm span";
  // Every joint's parent is the expected neighbour: children of the pelvis are below/above it.
  EXPECT_LT(j(1, 1), j(0, 1));
  EXPECT_GT(j(3, 1), j(0, 1));
}

TEST(DemoBody, JointRegressorRowsAreLocalAverages) {
  const BodyModel& m = demoBody();
  const Eigen::MatrixXd j = m.j_regressor * m.v_template;
  for (int k = 0; k < 24; ++k) {
    double sum = 0;
    int count = 0;
    double far = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(m.j_regressor, k); it;
         ++it) {
      EXPECT_GE(it.value(), 0.0);
      sum += it.value();
      ++count;
      far = std::max(far, (m.v_template.row(it.col()) - j.row(k)).norm());
    }
    EXPECT_NEAR(sum, 1.0, 1e-9) << "joint " << k;
    EXPECT_GE(count, 8) << "joint " << k;
    EXPECT_LT(far, 0.3) << "joint " << k << " uses far vertices";
  }
}

TEST(DemoBody, SkinWeightsAreSmoothAndFollowTheNearestBone) {
  const BodyModel& m = demoBody();
  const Eigen::MatrixXd j = m.j_regressor * m.v_template;
  // Bone of joint k: segment from J_k to its (first) child; leaves get none.
  std::vector<int> child(24, -1);
  for (int k = 23; k >= 1; --k) child[kSmplParents[k]] = k;
  child[0] = 3;   // pelvis -> spine1
  child[9] = 12;  // spine3 -> neck
  int many = 0, nearest_ok = 0, limb = 0;
  for (int i = 0; i < m.numVertices(); ++i) {
    EXPECT_NEAR(m.weights.row(i).sum(), 1.0, 1e-9);
    EXPECT_GE(m.weights.row(i).minCoeff(), 0.0);
    many += (m.weights.row(i).array() > 1e-3).count() > 4;
    // On the limbs (|x| > 0.25: arms), the largest weight belongs to the bone
    // nearest the vertex, or to the next one along where the bones meet.
    const Eigen::Vector3d p = m.v_template.row(i);
    if (std::abs(p.x()) < 0.25) continue;
    int best = -1;
    double best_d = 1e9;
    for (int k = 0; k < 24; ++k) {
      if (child[k] < 0) continue;
      const Eigen::Vector3d a = j.row(k), b = j.row(child[k]);
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const double d = (p - (a + t * (b - a))).norm();
      if (d < best_d) best_d = d, best = k;
    }
    int arg;
    m.weights.row(i).maxCoeff(&arg);
    ++limb;
    nearest_ok += arg == best || (best >= 0 && arg == child[best]) || arg == 22 || arg == 23;
  }
  std::printf("[demo] %d vertices with >4 influences; arm vertices on the nearest bone: %d of %d\n",
              many, nearest_ok, limb);
  EXPECT_GT(many, 20);
  EXPECT_GT(nearest_ok, 0.9 * limb);
  // Smooth: two vertices sharing an edge differ little in weight.
  double worst = 0;
  for (int t = 0; t < m.faces.rows(); ++t)
    for (int q = 0; q < 3; ++q)
      worst =
          std::max(worst, (m.weights.row(m.faces(t, q)) - m.weights.row(m.faces(t, (q + 1) % 3)))
                              .cwiseAbs()
                              .maxCoeff());
  EXPECT_LT(worst, 0.6);
}

TEST(DemoBody, ShapeDirectionsMoveTheBodyAsDocumented) {
  const BodyModel& m = demoBody();
  const double h0 = height(m.v_template), vol0 = signedVolume(m.v_template, m.faces);
  auto shaped = [&](int s, double value) {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(10);
    b[s] = value;
    Result<ShapedBody> r = shapeBody(m, b);
    EXPECT_TRUE(r.ok());
    return r.value();
  };
  const ShapedBody tall = shaped(0, 1.0), base = shaped(0, 0.0);
  EXPECT_GT(height(tall.v_shaped) - h0, 0.03);
  EXPECT_LT(height(tall.v_shaped) - h0, 0.10);
  EXPECT_GT(tall.joints(15, 1) - base.joints(15, 1), 0.03) << "head joint follows the height";
  EXPECT_LT(height(shaped(0, -2.0).v_shaped), h0 - 0.06);
  EXPECT_GT(signedVolume(shaped(1, 1.0).v_shaped, m.faces), 1.05 * vol0) << "girth";
  EXPECT_LT(signedVolume(shaped(1, -1.0).v_shaped, m.faces), 0.95 * vol0);
  const ShapedBody wide = shaped(2, 1.0);
  EXPECT_GT(wide.joints(16, 0) - base.joints(16, 0), 0.01) << "left shoulder moves out";
  EXPECT_LT(wide.joints(17, 0) - base.joints(17, 0), -0.01);
  EXPECT_GT(shaped(3, 1.0).joints(1, 0) - base.joints(1, 0), 0.01) << "hip width";
  EXPECT_GT(height(shaped(4, 1.0).v_shaped) - h0, 0.03) << "leg length";
  EXPECT_GT(shaped(5, 1.0).joints(22, 0) - base.joints(22, 0), 0.02) << "arm length";
  // All ten directions are distinct: the 3N x 10 matrix has full rank.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m.shapedirs);
  const Eigen::VectorXd sv = svd.singularValues();
  EXPECT_GT(sv[9], 1e-3 * sv[0]);
  for (int s = 0; s < 10; ++s) {
    const double biggest = (shaped(s, 1.0).v_shaped - m.v_template).rowwise().norm().maxCoeff();
    EXPECT_GT(biggest, 0.005) << "shape " << s;
    EXPECT_LT(biggest, 0.1) << "shape " << s;
  }
}

// A vertex skinned by one bone moves rigidly under DQS too; this pins the
// dual-quaternion code to the forward pass's transforms.
TEST(DemoBody, DualQuaternionTargetIsRigidForSingleBoneVertices) {
  const BodyModel& m = demoBody();
  const Rotations rot = rotationsFromAxisAngle(demo::sampleDemoPoses(1, 99)[0]);
  const Eigen::MatrixXd target = demo::dualQuaternionSkin(m, rot);
  ForwardInput in;
  in.rotations = rot;
  in.pose_correctives = false;
  Result<ForwardResult> lbs = forward(m, in);
  ASSERT_TRUE(lbs.ok()) << lbs.message();
  int rigid = 0;
  for (int i = 0; i < m.numVertices(); ++i) {
    if (m.weights.row(i).maxCoeff() < 1.0) continue;
    ++rigid;
    EXPECT_LT((target.row(i) - lbs->vertices.row(i)).norm(), 1e-9) << "vertex " << i;
  }
  EXPECT_GT(rigid, 100);
  const Eigen::MatrixXd rest =
      demo::dualQuaternionSkin(m, Rotations(24, Eigen::Matrix3d::Identity()));
  EXPECT_LT((rest - m.v_template).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DemoBody, CorrectivesBringLbsCloserToTheTargetOnHeldOutPoses) {
  const BodyModel& m = demoBody();
  // A different seed from the fit's, and poses from the shared sampler too.
  std::vector<Eigen::VectorXd> poses = demo::sampleDemoPoses(30, 20240601);
  for (const Eigen::VectorXd& pose : samplePoses(24, 10, 7, 0.5)) poses.push_back(pose);
  double before = 0, after = 0, worst_before = 0, worst_after = 0;
  for (const Eigen::VectorXd& pose : poses) {
    ForwardInput in;
    in.rotations = rotationsFromAxisAngle(pose);
    const Eigen::MatrixXd target = demo::dualQuaternionSkin(m, in.rotations);
    in.pose_correctives = false;
    const Eigen::MatrixXd lbs = forward(m, in)->vertices;
    in.pose_correctives = true;
    const Eigen::MatrixXd corrected = forward(m, in)->vertices;
    const Eigen::VectorXd e0 = (lbs - target).rowwise().norm(),
                          e1 = (corrected - target).rowwise().norm();
    before += e0.mean() / poses.size();
    after += e1.mean() / poses.size();
    worst_before = std::max(worst_before, e0.maxCoeff());
    worst_after = std::max(worst_after, e1.maxCoeff());
  }
  std::printf(
      "[demo] held-out mean vertex error vs DQS: LBS %.3f mm, LBS+correctives %.3f mm (%.1fx); "
      "worst %.1f -> %.1f mm\n",
      1e3 * before, 1e3 * after, before / after, 1e3 * worst_before, 1e3 * worst_after);
  EXPECT_GT(before, 2e-4) << "the poses bend the body enough to matter";
  EXPECT_LT(after, before / 4);
  EXPECT_LT(worst_after, worst_before);
}

TEST(DemoBody, BuildIsDeterministicAndFast) {
  const auto start = std::chrono::steady_clock::now();
  const BodyModel fresh = demo::buildDemoBody();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[demo] build time %.0f ms (this build type)\n", ms);
  const BodyModel& cached = demoBody();
  EXPECT_EQ(&cached, &demoBody()) << "memoised";
  EXPECT_TRUE(fresh.v_template == cached.v_template);
  EXPECT_TRUE(fresh.faces == cached.faces);
  EXPECT_TRUE(fresh.weights == cached.weights);
  EXPECT_TRUE(fresh.shapedirs == cached.shapedirs);
  EXPECT_TRUE(fresh.posedirs == cached.posedirs);
  EXPECT_TRUE(Eigen::MatrixXd(fresh.j_regressor) == Eigen::MatrixXd(cached.j_regressor));
}

}  // namespace
}  // namespace smpl
