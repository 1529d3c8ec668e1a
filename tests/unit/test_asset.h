// Small hand-made Assets for the writer, metadata and validation tests, built
// from the same few pieces so each test file states only what it varies:
//   skeletonFromWorld  names, parents and rest joint positions -> Skeleton
//                      (rest_local = J_k - J_parent(k), root: J_0)
//   makeAsset(spec)    a random but seeded asset (std::mt19937(1234)): a
//                      binary-tree skeleton (p(k) = (k-1)/2), a triangle strip,
//                      `influences` distinct joints per vertex with positive
//                      weights summing to 1, `morph_targets` correctives
//                      pose_joint_1_0<t> and, with frames > 0, one clip "walk"
//                      at 30 fps. Every asset it returns passes validateAsset.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>
#include <string>
#include <vector>

#include "exporter/asset.h"

namespace smpl::test {

// K joints from their names, parents (p(k) < k, -1 for the root) and rest
// positions (K x 3, metres).
inline Skeleton skeletonFromWorld(std::vector<std::string> names, std::vector<int> parents,
                                  const Eigen::MatrixXd& rest_world) {
  Skeleton s;
  s.names = std::move(names);
  s.parents = std::move(parents);
  s.rest_world = rest_world;
  s.rest_local = rest_world;
  for (size_t k = 0; k < s.parents.size(); ++k)
    if (s.parents[k] >= 0) s.rest_local.row(Eigen::Index(k)) -= rest_world.row(s.parents[k]);
  return s;
}

struct AssetSpec {
  int joints = 10;
  int vertices = 12;
  int influences = 4;
  bool uvs = true;
  int morph_targets = 2;
  int frames = 0;
};

inline Eigen::MatrixXf randomMatrix(std::mt19937& rng, int rows, int cols, float lo, float hi) {
  std::uniform_real_distribution<float> u(lo, hi);
  Eigen::MatrixXf m(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) m(r, c) = u(rng);
  return m;
}

inline Skeleton randomSkeleton(std::mt19937& rng, int k_count) {
  const Eigen::MatrixXd world = randomMatrix(rng, k_count, 3, -1.f, 1.f).cast<double>();
  std::vector<std::string> names;
  std::vector<int> parents;
  for (int k = 0; k < k_count; ++k) {
    names.push_back(k == 0 ? "pelvis" : "joint_" + std::to_string(k));
    parents.push_back(k == 0 ? -1 : (k - 1) / 2);  // a binary tree, p(k) < k
  }
  return skeletonFromWorld(names, parents, world);
}

// Distinct joints per vertex, positive weights summing to 1 in double.
inline void fillSkin(SkinnedMesh& m, std::mt19937& rng, int v_count, int k_count, int influences) {
  m.joints.resize(v_count, influences);
  m.weights.resize(v_count, influences);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  for (int v = 0; v < v_count; ++v) {
    std::vector<double> w(static_cast<size_t>(influences));
    double sum = 0;
    for (double& x : w) sum += (x = u(rng));
    for (int i = 0; i < influences; ++i) {
      m.joints(v, i) = (v + 3 * i) % k_count;
      m.weights(v, i) = float(w[size_t(i)] / sum);
    }
  }
}

inline void fillAnimation(Asset& a, std::mt19937& rng, int frames) {
  AnimationClip clip;
  clip.name = "walk";
  std::normal_distribution<double> n(0.0, 1.0);
  for (int t = 0; t < frames; ++t) clip.times.push_back(t / 30.0);
  clip.rotations.resize(a.skeleton.names.size());
  for (auto& track : clip.rotations)
    for (int t = 0; t < frames; ++t)
      track.push_back(
          Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().cast<float>());
  for (int t = 0; t < frames; ++t) clip.root_translation.emplace_back(n(rng), n(rng), n(rng));
  clip.morph_weights = randomMatrix(rng, frames, int(a.mesh.morph_targets.size()), -2.f, 1.f);
  a.animations.push_back(clip);
}

inline Asset makeAsset(const AssetSpec& spec) {
  std::mt19937 rng(1234);
  Asset a;
  a.name = "body";
  a.skeleton = randomSkeleton(rng, spec.joints);
  SkinnedMesh& m = a.mesh;
  const int v_count = spec.vertices;
  m.positions = randomMatrix(rng, v_count, 3, -1.f, 1.f);
  m.normals = randomMatrix(rng, v_count, 3, -1.f, 1.f).rowwise().normalized();
  if (spec.uvs) m.uvs = randomMatrix(rng, v_count, 2, 0.f, 1.f);
  m.triangles.resize(v_count - 2, 3);
  for (int f = 0; f < v_count - 2; ++f) m.triangles.row(f) << f, f + 1, f + 2;
  fillSkin(m, rng, v_count, spec.joints, spec.influences);
  for (int t = 0; t < spec.morph_targets; ++t)
    m.morph_targets.push_back(
        {"pose_joint_1_0" + std::to_string(t), randomMatrix(rng, v_count, 3, -0.1f, 0.1f)});
  a.metadata = {"smpl",
                "synthetic",
                "0.1.0",
                {0.5, -1.25},
                {},
                {{0, "pose_joint_1_00", 1.0, 0.0}},
                spec.influences,
                "meters",
                "+Y",
                {}};
  if (spec.frames > 0) fillAnimation(a, rng, spec.frames);
  return a;
}

// Engine playback of frame `f`: LBS of (base + sum w_t d_t) with node world
// transforms from the clip and inverse bind matrices translation(-J_k).
inline Eigen::MatrixXd enginePlayback(const Asset& a, const AnimationClip& clip, int f) {
  const Skeleton& s = a.skeleton;
  const size_t k = s.parents.size();
  std::vector<Eigen::Affine3d> world(k);
  for (size_t j = 0; j < k; ++j) {
    const bool track = j < clip.joint_translations.size() && !clip.joint_translations[j].empty();
    Eigen::Vector3d t = j == 0  ? clip.root_translation[f]
                        : track ? clip.joint_translations[j][f]
                                : Eigen::Vector3d(s.rest_local.row(j).transpose());
    Eigen::Affine3d local =
        Eigen::Translation3d(t) * clip.rotations[j][f].cast<double>().normalized();
    world[j] = s.parents[j] < 0 ? local : world[s.parents[j]] * local;
  }
  Eigen::MatrixXd v = a.mesh.positions.cast<double>();
  for (size_t t = 0; t < a.mesh.morph_targets.size(); ++t)
    v += double(clip.morph_weights(f, t)) * a.mesh.morph_targets[t].peak *
         a.mesh.morph_targets[t].deltas.cast<double>();
  Eigen::MatrixXd out(v.rows(), 3);
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (Eigen::Index m = 0; m < a.mesh.joints.cols(); ++m) {
      const int j = a.mesh.joints(i, m);
      p += double(a.mesh.weights(i, m)) *
           (world[j] * (Eigen::Vector3d(v.row(i).transpose()) -
                        Eigen::Vector3d(s.rest_world.row(j).transpose())));
    }
    out.row(i) = p.transpose();
  }
  return out;
}

}  // namespace smpl::test
