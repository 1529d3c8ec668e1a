#include "exporter/placement.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace smpl {
namespace {

using Affine = Eigen::Matrix<double, 3, 4>;

// Local translation of joint k at frame t (AnimationClip: root_translation,
// joint_translations, else the rest offset).
Eigen::Vector3d localTranslation(const Asset& a, const AnimationClip& c, size_t k, size_t t) {
  if (k == 0 && !c.root_translation.empty()) return c.root_translation[t];
  if (k < c.joint_translations.size() && !c.joint_translations[k].empty())
    return c.joint_translations[k][t];
  return a.skeleton.rest_local.row(Eigen::Index(k)).transpose();
}

// Skinning transforms A_k = G_k translation(-J_k) of frame t (parents precede children).
std::vector<Affine> skinningTransforms(const Asset& a, const AnimationClip& c, size_t t) {
  const Skeleton& s = a.skeleton;
  const size_t k_count = s.names.size();
  std::vector<Eigen::Matrix3d> r(k_count);
  std::vector<Eigen::Vector3d> g(k_count);
  std::vector<Affine> out(k_count);
  for (size_t k = 0; k < k_count; ++k) {
    const Eigen::Matrix3d local = c.rotations[k][t].cast<double>().normalized().toRotationMatrix();
    const Eigen::Vector3d tr = localTranslation(a, c, k, t);
    const int p = s.parents[k];
    r[k] = p < 0 ? local : Eigen::Matrix3d(r[size_t(p)] * local);
    g[k] = p < 0 ? tr : Eigen::Vector3d(r[size_t(p)] * tr + g[size_t(p)]);
    out[k].leftCols<3>() = r[k];
    out[k].col(3) = g[k] - r[k] * s.rest_world.row(Eigen::Index(k)).transpose();
  }
  return out;
}

// sum_n |deltas_n,v| peak_n per vertex: how far all morph targets at weight 1 can move v.
Eigen::VectorXd morphReach(const SkinnedMesh& m) {
  Eigen::VectorXd reach = Eigen::VectorXd::Zero(m.positions.rows());
  for (const MorphTarget& t : m.morph_targets)
    reach += (t.deltas.cast<double>().rowwise().norm() * t.peak).eval();
  return reach;
}

// The morph displacement of vertex v at weights w (one per target).
Eigen::Vector3d morphAt(const SkinnedMesh& m, Eigen::Index v, const Eigen::VectorXf& w) {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (size_t n = 0; n < m.morph_targets.size(); ++n)
    if (w[Eigen::Index(n)] != 0.0f)
      d += double(w[Eigen::Index(n)]) * m.morph_targets[n].peak *
           m.morph_targets[n].deltas.row(v).transpose().cast<double>();
  return d;
}

// Row y of the blended skinning transform of vertex v: y = a . q + b.
Eigen::Vector4d blendedRowY(const SkinnedMesh& m, const std::vector<Affine>& A, Eigen::Index v) {
  Eigen::Vector4d row = Eigen::Vector4d::Zero();
  for (Eigen::Index i = 0; i < m.joints.cols(); ++i)
    row += double(m.weights(v, i)) * A[size_t(m.joints(v, i))].row(1).transpose();
  return row;
}

// Lowest posed y of one frame: skin every vertex without morphs, then the
// exact morph only where the bound leaves the vertex a candidate.
double lowestOfFrame(const Asset& a, const AnimationClip& c, size_t t,
                     const Eigen::VectorXd& reach) {
  const SkinnedMesh& m = a.mesh;
  const std::vector<Affine> A = skinningTransforms(a, c, t);
  const Eigen::Index v_count = m.positions.rows();
  Eigen::VectorXf w = Eigen::VectorXf::Zero(Eigen::Index(m.morph_targets.size()));
  if (c.morph_weights.size() > 0) w = c.morph_weights.row(Eigen::Index(t)).transpose();
  const double w_max = w.size() > 0 ? double(w.cwiseAbs().maxCoeff()) : 0.0;
  Eigen::Matrix<double, Eigen::Dynamic, 4> rows(v_count, 4);  // blended row y per vertex
  Eigen::VectorXd y0(v_count);
  double bound = std::numeric_limits<double>::infinity();
  for (Eigen::Index v = 0; v < v_count; ++v) {
    rows.row(v) = blendedRowY(m, A, v).transpose();
    y0[v] = rows.row(v).head<3>().dot(m.positions.row(v).cast<double>()) + rows(v, 3);
    bound = std::min(bound, y0[v] + w_max * reach[v]);
  }
  double lowest = std::numeric_limits<double>::infinity();
  for (Eigen::Index v = 0; v < v_count; ++v) {
    if (y0[v] - w_max * reach[v] > bound) continue;
    const double y =
        w_max > 0 ? y0[v] + rows.row(v).head<3>().dot(morphAt(m, v, w).transpose()) : y0[v];
    lowest = std::min(lowest, y);
  }
  return lowest;
}

double lowestAtRest(const SkinnedMesh& m) {
  Eigen::VectorXd y = m.positions.col(1).cast<double>();
  for (const MorphTarget& t : m.morph_targets)
    if (t.rest_weight != 0.0f) y += double(t.rest_weight) * t.peak * t.deltas.col(1).cast<double>();
  return y.minCoeff();
}

}  // namespace

double lowestPoint(const Asset& asset) {
  const SkinnedMesh& m = asset.mesh;
  if (m.positions.rows() == 0) return std::numeric_limits<double>::infinity();
  if (asset.animations.empty()) return lowestAtRest(m);
  const Eigen::VectorXd reach = morphReach(m);
  double lowest = std::numeric_limits<double>::infinity();
  for (const AnimationClip& c : asset.animations)
    for (size_t t = 0; t < c.times.size(); ++t)
      lowest = std::min(lowest, lowestOfFrame(asset, c, t, reach));
  return lowest;
}

void shiftAssetUp(Asset* asset, double dy) {
  asset->placement.origin = "floor";
  asset->placement.floor_offset += dy;
  if (asset->mesh.positions.rows() > 0) asset->mesh.positions.col(1).array() += float(dy);
  Skeleton& s = asset->skeleton;
  if (s.rest_world.rows() > 0) s.rest_world.col(1).array() += dy;
  if (s.rest_local.rows() > 0) s.rest_local(0, 1) += dy;  // only the root is placed in the world
  for (AnimationClip& c : asset->animations) {
    for (Eigen::Vector3d& p : c.root_translation) p.y() += dy;
    if (!c.joint_translations.empty())
      for (Eigen::Vector3d& p : c.joint_translations[0]) p.y() += dy;
  }
}

void addRootBone(Asset* asset) {
  Skeleton& s = asset->skeleton;
  const Eigen::Index k_count = Eigen::Index(s.names.size());
  const Eigen::Vector3d j0 = s.rest_world.row(0).transpose();
  const Eigen::Vector3d ground(j0.x(), 0.0, j0.z());
  s.names.insert(s.names.begin(), "root");
  std::vector<int> parents = {-1};
  for (int p : s.parents) parents.push_back(p < 0 ? 0 : p + 1);
  s.parents = parents;
  Eigen::MatrixXd world(k_count + 1, 3), local(k_count + 1, 3);
  world.row(0) = ground.transpose();
  world.bottomRows(k_count) = s.rest_world;
  local.row(0) = ground.transpose();
  local.bottomRows(k_count) = s.rest_local;
  local.row(1) = (j0 - ground).transpose();
  s.rest_world = world;
  s.rest_local = local;
  if (asset->mesh.joints.size() > 0) asset->mesh.joints.array() += 1;
  for (AnimationClip& c : asset->animations) {
    const size_t t_count = c.times.size();
    c.rotations.insert(c.rotations.begin(), RotationTrack(t_count, Eigen::Quaternionf::Identity()));
    std::vector<Eigen::Vector3d> root(t_count), pelvis(t_count);
    for (size_t t = 0; t < t_count; ++t) {
      const Eigen::Vector3d p = c.root_translation.empty() ? j0 : c.root_translation[t];
      root[t] = Eigen::Vector3d(p.x(), 0.0, p.z());
      pelvis[t] = Eigen::Vector3d(0.0, p.y(), 0.0);
    }
    std::vector<std::vector<Eigen::Vector3d>> tracks(size_t(k_count) + 1);
    for (size_t k = 1; k < c.joint_translations.size(); ++k)
      tracks[k + 1] = std::move(c.joint_translations[k]);
    tracks[0] = root;
    tracks[1] = std::move(pelvis);
    c.joint_translations = std::move(tracks);
    c.root_translation = std::move(root);
  }
  asset->placement.root_bone = true;
}

}  // namespace smpl
