// A small synthetic Asset for the FBX tests (fbx_writer_test.cpp,
// fbx_assimp_test.cpp): a 1.7 m capsule-like cylinder standing on +Y with a
// 5-joint skeleton (pelvis -> spine -> head, pelvis -> left/right leg), two
// influences per vertex, three morph targets (dense, sparse, all-zero) and a
// 10-frame clip at 30 fps, plus the world joint positions that clip implies
// (plain forward kinematics, independent of the writer).
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <vector>

#include "exporter/asset.h"
#include "tests/unit/test_asset.h"

namespace smpl {
namespace fbx_test {

constexpr int kSegments = 8;
constexpr int kRings = 6;
constexpr double kPi = 3.14159265358979323846;

// Deterministic pseudo-random numbers in [-1, 1] (no <random> differences).
struct Lcg {
  uint64_t state = 12345;
  double next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53) * 2.0 - 1.0;
  }
};

inline Skeleton testSkeleton() {
  Eigen::MatrixXd rest_world(5, 3);
  rest_world << 0, 0.9, 0, 0, 1.2, 0.02, 0, 1.5, 0, 0.1, 0.5, 0, -0.1, 0.5, 0;
  return test::skeletonFromWorld({"pelvis", "spine", "head", "left_leg", "right_leg"},
                                 {-1, 0, 1, 0, 0}, rest_world);
}

// Cylinder: kRings rings of kSegments vertices from y=0 to y=1.7, plus a
// bottom and a top centre vertex: 50 vertices.
inline void buildCylinder(SkinnedMesh& m) {
  const int v_count = kSegments * kRings + 2;
  m.positions.resize(v_count, 3);
  m.normals.resize(v_count, 3);
  m.uvs.resize(v_count, 2);
  for (int r = 0; r < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      double a = 2 * kPi * s / kSegments, y = 1.7 * r / (kRings - 1);
      int v = r * kSegments + s;
      m.positions.row(v) << float(0.15 * std::cos(a)), float(y), float(-0.15 * std::sin(a));
      m.normals.row(v) << float(std::cos(a)), 0.0f, float(-std::sin(a));
      m.uvs.row(v) << float(s) / kSegments, float(r) / (kRings - 1);
    }
  const int bottom = v_count - 2, top = v_count - 1;
  m.positions.row(bottom) << 0, 0, 0;
  m.positions.row(top) << 0, 1.7f, 0;
  m.normals.row(bottom) << 0, -1, 0;
  m.normals.row(top) << 0, 1, 0;
  m.uvs.row(bottom) << 0.5f, 0;
  m.uvs.row(top) << 0.5f, 1;
  std::vector<Eigen::Vector3i> tris;
  for (int r = 0; r + 1 < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      int a = r * kSegments + s, b = r * kSegments + (s + 1) % kSegments;
      int c = a + kSegments, d = b + kSegments;
      tris.emplace_back(a, b, d);  // angle grows counter-clockwise seen from +Y
      tris.emplace_back(a, d, c);
    }
  for (int s = 0; s < kSegments; ++s) {
    int s1 = (s + 1) % kSegments;
    tris.emplace_back(bottom, s1, s);
    tris.emplace_back(top, (kRings - 1) * kSegments + s, (kRings - 1) * kSegments + s1);
  }
  m.triangles.resize(int(tris.size()), 3);
  for (size_t i = 0; i < tris.size(); ++i) m.triangles.row(int(i)) = tris[i].transpose();
}

// Two influences: the nearest joint and the second nearest, inverse distance.
inline void skinToNearest(SkinnedMesh& m, const Skeleton& s) {
  m.joints.resize(m.positions.rows(), 2);
  m.weights.resize(m.positions.rows(), 2);
  for (Eigen::Index v = 0; v < m.positions.rows(); ++v) {
    Eigen::Vector3d p = m.positions.row(v).cast<double>().transpose();
    int best = 0, second = 1;
    std::vector<double> d(s.names.size());
    for (size_t k = 0; k < d.size(); ++k)
      d[k] = (p - s.rest_world.row(k).transpose()).norm() + 1e-3;
    for (int k = 0; k < int(d.size()); ++k)
      if (d[k] < d[best]) best = k;
    second = best == 0 ? 1 : 0;
    for (int k = 0; k < int(d.size()); ++k)
      if (k != best && d[k] < d[second]) second = k;
    double wb = 1 / d[best], ws = 1 / d[second];
    m.joints.row(v) << best, second;
    m.weights.row(v) << float(wb / (wb + ws)), float(ws / (wb + ws));
  }
}

inline void addMorphTargets(SkinnedMesh& m) {
  Lcg rng;
  MorphTarget dense{"pose_spine_00", Eigen::MatrixXf(m.positions.rows(), 3)};
  for (Eigen::Index i = 0; i < dense.deltas.size(); ++i) dense.deltas(i) = float(0.02 * rng.next());
  MorphTarget sparse{"pose_head_12", Eigen::MatrixXf::Zero(m.positions.rows(), 3)};
  for (Eigen::Index v = 0; v < m.positions.rows(); ++v)
    if (m.positions(v, 1) > 1.3f) sparse.deltas.row(v) << 0.01f, 0.03f, -0.02f;
  MorphTarget zero{"shape_zero", Eigen::MatrixXf::Zero(m.positions.rows(), 3)};
  m.morph_targets = {dense, sparse, zero};
}

inline AnimationClip testClip(int targets) {
  AnimationClip c;
  c.name = "wave";
  c.fps = 30;
  const int frames = 10;
  c.rotations.assign(5, {});
  c.morph_weights.resize(frames, targets);
  for (int f = 0; f < frames; ++f) {
    double t = double(f) / (frames - 1);
    c.times.push_back(f / c.fps);
    // The pelvis turns 270 degrees about +Y: Euler curves must stay continuous.
    auto key = [](const Eigen::AngleAxisd& r) { return Eigen::Quaterniond(r).cast<float>(); };
    c.rotations[0].push_back(key(Eigen::AngleAxisd(1.5 * kPi * t, Eigen::Vector3d::UnitY())));
    c.rotations[1].push_back(
        key(Eigen::AngleAxisd(0.8 * t, Eigen::Vector3d(0.3, 0.2, 1).normalized())));
    c.rotations[2].push_back(key(Eigen::AngleAxisd(-0.6 * t, Eigen::Vector3d::UnitX())));
    c.rotations[3].push_back(
        key(Eigen::AngleAxisd(0.5 * t, Eigen::Vector3d(1, 0, 0.4).normalized())));
    c.rotations[4].push_back(Eigen::Quaternionf::Identity());
    c.root_translation.emplace_back(0.05 * t, 0.9 + 0.02 * t, 0.3 * t);
    for (int m = 0; m < targets; ++m)
      c.morph_weights(f, m) = float(0.5 + 0.5 * std::sin(3 * t + m));
  }
  return c;
}

inline Asset testAsset() {
  Asset a;
  a.name = "body";
  a.skeleton = testSkeleton();
  buildCylinder(a.mesh);
  skinToNearest(a.mesh, a.skeleton);
  addMorphTargets(a.mesh);
  a.animations.push_back(testClip(int(a.mesh.morph_targets.size())));
  a.mesh.source_vertex.resize(a.mesh.positions.rows());
  for (int i = 0; i < int(a.mesh.source_vertex.size()); ++i) a.mesh.source_vertex[i] = i;
  return a;
}

// World joint positions of frame f: G_k = G_p * [R_k | t_k], with the root's
// translation taken from the clip.
inline std::vector<Eigen::Vector3d> worldJoints(const Asset& a, const AnimationClip& c, int f) {
  const Skeleton& s = a.skeleton;
  std::vector<Eigen::Isometry3d> g(s.names.size());
  std::vector<Eigen::Vector3d> out;
  for (size_t k = 0; k < s.names.size(); ++k) {
    Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
    local.linear() = c.rotations[k][f].cast<double>().toRotationMatrix();
    local.translation() =
        k == 0 ? c.root_translation[f] : Eigen::Vector3d(s.rest_local.row(k).transpose());
    g[k] = s.parents[k] < 0 ? local : g[s.parents[k]] * local;
    out.push_back(g[k].translation());
  }
  return out;
}

}  // namespace fbx_test
}  // namespace smpl
