// Input checks of the FBX writer: every size and index the scene builders
// rely on, so they can index without bounds checks (fbx_scene_internal.h).
#include <cmath>

#include "plugins/fbx/fbx_scene_internal.h"

namespace smpl {
namespace fbx {
namespace {

std::string sizeText(Eigen::Index rows, Eigen::Index cols) {
  return "(" + std::to_string(rows) + "," + std::to_string(cols) + ")";
}

Status checkSkeleton(const Skeleton& s) {
  const size_t k = s.names.size();
  if (k == 0) return makeError("FBX: asset has no joints");
  if (s.parents.size() != k)
    return makeError("FBX: skeleton has " + std::to_string(k) + " names but " +
                     std::to_string(s.parents.size()) + " parents");
  for (size_t j = 0; j < k; ++j)
    if (s.parents[j] < -1 || s.parents[j] >= static_cast<int>(j))
      return makeError("FBX: joint " + std::to_string(j) + " has parent " +
                       std::to_string(s.parents[j]) + "; expected -1 <= parent < joint");
  if (s.rest_local.rows() != Eigen::Index(k) || s.rest_local.cols() != 3 ||
      s.rest_world.rows() != Eigen::Index(k) || s.rest_world.cols() != 3)
    return makeError("FBX: rest_local " + sizeText(s.rest_local.rows(), s.rest_local.cols()) +
                     " / rest_world " + sizeText(s.rest_world.rows(), s.rest_world.cols()) +
                     "; expected (" + std::to_string(k) + ",3)");
  return Status::success();
}

Status checkMesh(const SkinnedMesh& m, int joints) {
  const Eigen::Index v = m.positions.rows();
  if (v == 0 || m.positions.cols() != 3)
    return makeError("FBX: mesh positions " + sizeText(v, m.positions.cols()) +
                     "; expected (V,3), V > 0");
  if (m.normals.rows() != 0 && (m.normals.rows() != v || m.normals.cols() != 3))
    return makeError("FBX: mesh normals " + sizeText(m.normals.rows(), m.normals.cols()) +
                     "; expected (" + std::to_string(v) + ",3)");
  if (m.uvs.rows() != 0 && (m.uvs.rows() != v || m.uvs.cols() != 2))
    return makeError("FBX: mesh uvs " + sizeText(m.uvs.rows(), m.uvs.cols()) + "; expected (" +
                     std::to_string(v) + ",2)");
  if (m.triangles.cols() != 3 || m.triangles.rows() == 0)
    return makeError("FBX: mesh triangles " + sizeText(m.triangles.rows(), m.triangles.cols()) +
                     "; expected (F,3), F > 0");
  if (m.triangles.minCoeff() < 0 || m.triangles.maxCoeff() >= v)
    return makeError("FBX: triangle index out of range [0," + std::to_string(v) + ")");
  if (m.joints.rows() != v || m.weights.rows() != v || m.joints.cols() != m.weights.cols())
    return makeError("FBX: skin joints " + sizeText(m.joints.rows(), m.joints.cols()) +
                     " / weights " + sizeText(m.weights.rows(), m.weights.cols()) +
                     "; expected equal shapes (" + std::to_string(v) + ",M)");
  if (m.joints.size() > 0 && (m.joints.minCoeff() < 0 || m.joints.maxCoeff() >= joints))
    return makeError("FBX: skin joint index out of range [0," + std::to_string(joints) + ")");
  for (const MorphTarget& t : m.morph_targets)
    if (t.deltas.rows() != v || t.deltas.cols() != 3)
      return makeError("FBX: morph target '" + t.name + "' deltas " +
                       sizeText(t.deltas.rows(), t.deltas.cols()) + "; expected (" +
                       std::to_string(v) + ",3)");
  return Status::success();
}

Status checkClip(const AnimationClip& c, size_t joints, size_t targets) {
  const size_t t = c.times.size();
  const std::string where = "FBX: animation '" + c.name + "': ";
  if (!(c.fps > 0) || !std::isfinite(c.fps)) return makeError(where + "fps must be positive");
  for (size_t i = 0; i < t; ++i)
    if (!std::isfinite(c.times[i]) || (i > 0 && c.times[i] < c.times[i - 1]))
      return makeError(where + "times must be finite and non-decreasing");
  if (c.rotations.size() != joints)
    return makeError(where + std::to_string(c.rotations.size()) + " rotation tracks; expected " +
                     std::to_string(joints));
  for (size_t k = 0; k < c.rotations.size(); ++k) {
    if (c.rotations[k].size() != t)
      return makeError(where + "joint " + std::to_string(k) + " has " +
                       std::to_string(c.rotations[k].size()) + " rotation keys; expected " +
                       std::to_string(t));
    for (const Eigen::Quaterniond& q : c.rotations[k])
      if (!std::isfinite(q.squaredNorm()) || q.squaredNorm() < 1e-12)
        return makeError(where + "joint " + std::to_string(k) +
                         " has a zero or non-finite rotation");
  }
  for (const Eigen::Vector3d& p : c.root_translation)
    if (!p.allFinite()) return makeError(where + "non-finite root translation");
  if (!c.root_translation.empty() && c.root_translation.size() != t)
    return makeError(where + std::to_string(c.root_translation.size()) +
                     " root translations; expected " + std::to_string(t));
  if (!c.joint_translations.empty() && c.joint_translations.size() != joints)
    return makeError(where + std::to_string(c.joint_translations.size()) + " translation tracks; expected " +
                     std::to_string(joints));
  for (const auto& track : c.joint_translations)
    if (track.size() != t) return makeError(where + "a translation track's length is not " + std::to_string(t));
  if (c.morph_weights.size() != 0 && (c.morph_weights.rows() != Eigen::Index(t) ||
                                      c.morph_weights.cols() != Eigen::Index(targets)))
    return makeError(where + "morph weights " +
                     sizeText(c.morph_weights.rows(), c.morph_weights.cols()) + "; expected (" +
                     std::to_string(t) + "," + std::to_string(targets) + ")");
  return Status::success();
}

}  // namespace

Status validateInput(const Asset& a, const WriterOptions& o) {
  if (o.fbx_units != "m" && o.fbx_units != "cm")
    return makeError("FBX: units '" + o.fbx_units + "'; expected m or cm");
  if (o.fbx_version != 7400 && o.fbx_version != 7500)
    return makeError("FBX: version " + std::to_string(o.fbx_version) + "; expected 7400 or 7500");
  Status s = checkSkeleton(a.skeleton);
  if (s.ok()) s = checkMesh(a.mesh, static_cast<int>(a.skeleton.names.size()));
  for (size_t i = 0; s.ok() && i < a.animations.size(); ++i)
    s = checkClip(a.animations[i], a.skeleton.names.size(), a.mesh.morph_targets.size());
  return s;
}

}  // namespace fbx
}  // namespace smpl
