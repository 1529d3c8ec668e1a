// validateAssetStructure: shapes first (so later loops may index), then
// indices and orderings; the first problem is named with its place.
#include "exporter/validate_structure.h"

#include <cmath>
#include <string>

#include "exporter/asset_names.h"

namespace smpl {
namespace {

std::string shapeText(Eigen::Index rows, Eigen::Index cols) {
  return "(" + std::to_string(rows) + "," + std::to_string(cols) + ")";
}

Status expectShape(const std::string& what, Eigen::Index rows, Eigen::Index cols,
                   Eigen::Index want_rows, Eigen::Index want_cols) {
  if (rows == want_rows && cols == want_cols) return Status();
  return makeError(what + " has shape " + shapeText(rows, cols) + "; expected " +
                   shapeText(want_rows, want_cols));
}

Status checkSkeleton(const Skeleton& s) {
  const Eigen::Index k = Eigen::Index(s.names.size());
  if (k == 0) return makeError("skeleton has no joints; expected at least one");
  if (Eigen::Index(s.parents.size()) != k)
    return makeError("skeleton has " + std::to_string(k) + " names but " +
                     std::to_string(s.parents.size()) + " parents; expected one parent per joint");
  if (s.parents[0] != -1)
    return makeError("joint 0 ('" + s.names[0] + "') has parent " + std::to_string(s.parents[0]) +
                     "; expected -1 (the root)");
  for (Eigen::Index j = 1; j < k; ++j)  // p(j) < j: no loops, joint 0 the only root
    if (s.parents[size_t(j)] < 0 || s.parents[size_t(j)] >= j)
      return makeError("joint " + std::to_string(j) + " ('" + s.names[size_t(j)] +
                       "') has parent " + std::to_string(s.parents[size_t(j)]) + "; expected 0.." +
                       std::to_string(j - 1) + " (one root)");
  Status st = expectShape("skeleton rest_local", s.rest_local.rows(), s.rest_local.cols(), k, 3);
  if (st) st = expectShape("skeleton rest_world", s.rest_world.rows(), s.rest_world.cols(), k, 3);
  return st;
}

Status checkShapes(const SkinnedMesh& m) {
  const Eigen::Index v = m.positions.rows();
  if (v == 0) return makeError("mesh has no vertices; expected V > 0");
  Status st = expectShape("mesh positions", v, m.positions.cols(), v, 3);
  if (st) st = expectShape("mesh normals", m.normals.rows(), m.normals.cols(), v, 3);
  if (st && m.uvs.rows() != 0) st = expectShape("mesh uvs", m.uvs.rows(), m.uvs.cols(), v, 2);
  if (st && (m.triangles.rows() == 0 || m.triangles.cols() != 3))
    st = makeError("mesh triangles have shape " +
                   shapeText(m.triangles.rows(), m.triangles.cols()) + "; expected (F,3), F > 0");
  if (st && m.joints.cols() == 0)
    st = makeError("mesh has no skin influences; expected (V,M), M > 0");
  if (st)
    st = expectShape("mesh skin joints", m.joints.rows(), m.joints.cols(), v, m.joints.cols());
  if (st)
    st = expectShape("mesh skin weights", m.weights.rows(), m.weights.cols(), v, m.joints.cols());
  for (size_t n = 0; st && n < m.morph_targets.size(); ++n) {
    const MorphTarget& t = m.morph_targets[n];
    st = expectShape("morph target '" + t.name + "'", t.deltas.rows(), t.deltas.cols(), v, 3);
  }
  return st;
}

Status checkSkin(const SkinnedMesh& m, int joints) {
  for (Eigen::Index v = 0; v < m.joints.rows(); ++v) {
    double sum = 0;
    for (Eigen::Index i = 0; i < m.joints.cols(); ++i) {
      if (m.joints(v, i) < 0 || m.joints(v, i) >= joints)
        return makeError("vertex " + std::to_string(v) + " uses joint " +
                         std::to_string(m.joints(v, i)) + "; expected 0.." +
                         std::to_string(joints - 1));
      if (!(m.weights(v, i) >= 0))
        return makeError("vertex " + std::to_string(v) + " has skin weight " +
                         std::to_string(m.weights(v, i)) + "; expected >= 0");
      sum += m.weights(v, i);
    }
    if (!(sum > 0))
      return makeError("vertex " + std::to_string(v) + " has no positive skin weight");
  }
  return Status();
}

Status checkMesh(const SkinnedMesh& m, int joints) {
  if (Status st = checkShapes(m); !st) return st;
  const Eigen::Index v = m.positions.rows();
  if (m.triangles.minCoeff() < 0 || m.triangles.maxCoeff() >= v)
    return makeError("mesh triangle index out of range; expected 0.." + std::to_string(v - 1));
  if (Status st = checkSkin(m, joints); !st) return st;
  for (const MorphTarget& t : m.morph_targets)
    if (t.quantized && t.deltas.size() && t.deltas.cwiseAbs().maxCoeff() > 1.f)
      return makeError("morph target '" + t.name + "' is quantized but has |delta| " +
                       std::to_string(t.deltas.cwiseAbs().maxCoeff()) +
                       "; expected <= 1 (morph_scales.h)");
  return Status();
}

Status checkTimes(const AnimationClip& c, const std::string& where) {
  if (c.times.empty()) return makeError(where + "no frames; expected T > 0");
  if (!(c.fps > 0) || !std::isfinite(c.fps))
    return makeError(where + "fps " + std::to_string(c.fps) + "; expected > 0");
  for (size_t t = 0; t < c.times.size(); ++t) {
    const float now = float(c.times[t]);  // as the files store them
    if (!std::isfinite(c.times[t]) || now < 0)
      return makeError(where + "key time of frame " + std::to_string(t) + " is " +
                       std::to_string(c.times[t]) + "; expected finite and >= 0");
    if (t > 0 && !(now > float(c.times[t - 1])))
      return makeError(where + "key time of frame " + std::to_string(t) + " (" +
                       std::to_string(now) + ") is not after frame " + std::to_string(t - 1) +
                       "; expected strictly increasing times");
  }
  return Status();
}

Status checkClip(const AnimationClip& c, size_t joints, Eigen::Index targets) {
  const std::string where = "animation '" + c.name + "': ";
  if (Status st = checkTimes(c, where); !st) return st;
  const size_t t = c.times.size();
  if (c.rotations.size() != joints)
    return makeError(where + std::to_string(c.rotations.size()) + " rotation tracks; expected " +
                     std::to_string(joints) + " (one per joint)");
  for (size_t k = 0; k < joints; ++k) {
    if (c.rotations[k].size() != t)
      return makeError(where + "joint " + std::to_string(k) + " has " +
                       std::to_string(c.rotations[k].size()) + " rotation keys; expected " +
                       std::to_string(t));
    for (const Eigen::Quaternionf& q : c.rotations[k])
      if (!std::isfinite(q.squaredNorm()) || q.squaredNorm() < 1e-12)
        return makeError(where + "joint " + std::to_string(k) +
                         " has a zero or non-finite rotation");
  }
  if (!c.root_translation.empty() && c.root_translation.size() != t)
    return makeError(where + std::to_string(c.root_translation.size()) +
                     " root translations; expected " + std::to_string(t));
  if (!c.joint_translations.empty() && c.joint_translations.size() != joints)
    return makeError(where + std::to_string(c.joint_translations.size()) +
                     " translation tracks; expected " + std::to_string(joints));
  for (const auto& track : c.joint_translations)  // empty: the joint stays at its rest offset
    if (!track.empty() && track.size() != t)
      return makeError(where + "a translation track's length is not " + std::to_string(t));
  if (c.morph_weights.size() == 0) return Status();  // no weight channel (T x 0 without targets)
  return expectShape(where + "morph weights", c.morph_weights.rows(), c.morph_weights.cols(),
                     Eigen::Index(t), targets);
}

}  // namespace

Status validateAssetStructure(const Asset& a) {
  if (Status st = checkAssetNames(a); !st) return st;  // text every format stores as UTF-8
  if (Status st = checkSkeleton(a.skeleton); !st) return st;
  if (a.skeleton_only && (a.mesh.positions.rows() != 0 || !a.mesh.morph_targets.empty()))
    return makeError("skeleton-only asset has " + std::to_string(a.mesh.positions.rows()) +
                     " mesh vertices and " + std::to_string(a.mesh.morph_targets.size()) +
                     " morph targets; expected none");
  if (a.skeleton_only) {
  } else if (Status st = checkMesh(a.mesh, int(a.skeleton.names.size())); !st) {
    return st;
  }
  for (const AnimationClip& clip : a.animations)
    if (Status st =
            checkClip(clip, a.skeleton.names.size(), Eigen::Index(a.mesh.morph_targets.size()));
        !st)
      return st;
  return Status();
}

}  // namespace smpl
