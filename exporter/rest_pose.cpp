// --rest-pose a (rest_pose.h).
#include "exporter/rest_pose.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/math/rotation.h"

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

int indexOf(const Skeleton& s, const std::string& name) {
  for (size_t k = 0; k < s.names.size(); ++k)
    if (s.names[k] == name) return int(k);
  return -1;
}

// G_k: the A pose's world rotation of every joint (parents come first).
std::vector<Eigen::Quaterniond> aWorldRotations(const Skeleton& s, int left, int right) {
  const double angle = kAPoseDegrees * kPi / 180.0;
  std::vector<Eigen::Quaterniond> world(s.names.size(), Eigen::Quaterniond::Identity());
  for (size_t k = 0; k < s.names.size(); ++k) {
    Eigen::Quaterniond local = Eigen::Quaterniond::Identity();
    if (int(k) == left) local = axisAngleQuaternion(-angle, Eigen::Vector3d::UnitZ());
    if (int(k) == right) local = axisAngleQuaternion(angle, Eigen::Vector3d::UnitZ());
    world[k] = s.parents[k] < 0 ? local : world[size_t(s.parents[k])] * local;
  }
  return world;
}

void reexpressSkeleton(const std::vector<Eigen::Quaterniond>& g, Skeleton* s) {
  const Eigen::MatrixXd joints = s->rest_world;
  for (size_t k = 0; k < s->names.size(); ++k) {
    const int p = s->parents[k];
    if (p < 0) continue;  // the root stays at J_root
    const Eigen::Vector3d bone = (joints.row(Eigen::Index(k)) - joints.row(p)).transpose();
    const Eigen::Vector3d offset = g[size_t(p)] * bone;
    s->rest_local.row(Eigen::Index(k)) = offset.transpose();
    s->rest_world.row(Eigen::Index(k)) = s->rest_world.row(p) + offset.transpose();
  }
}

void reexpressClip(const Skeleton& s, const std::vector<Eigen::Quaterniond>& g,
                   AnimationClip* clip) {
  for (size_t k = 0; k < clip->rotations.size(); ++k) {
    const Eigen::Quaterniond parent =
        s.parents[k] < 0 ? Eigen::Quaterniond::Identity() : g[size_t(s.parents[k])];
    const Eigen::Quaterniond inverse = g[k].conjugate();
    for (Eigen::Quaternionf& q : clip->rotations[k])
      q = (parent * q.cast<double>().normalized() * inverse).normalized().cast<float>();
  }
  for (size_t k = 1; k < clip->joint_translations.size(); ++k)
    for (Eigen::Vector3d& t : clip->joint_translations[k]) t = g[size_t(s.parents[k])] * t;
}

}  // namespace

Status applyARestPose(Asset* asset) {
  Skeleton& s = asset->skeleton;
  const int left = indexOf(s, "left_shoulder"), right = indexOf(s, "right_shoulder");
  if (left < 0 || right < 0)
    return makeError(
        "--rest-pose a: the skeleton has no left_shoulder and right_shoulder joints "
        "(an A pose lowers the arms of a body model)");
  if (!asset->skeleton_only)
    return makeError(
        "--rest-pose a: only a skeleton without a mesh (.bvh) can change its rest "
        "exactly");
  const std::vector<Eigen::Quaterniond> g = aWorldRotations(s, left, right);
  for (AnimationClip& clip : asset->animations) reexpressClip(s, g, &clip);
  reexpressSkeleton(g, &s);
  asset->metadata.rest_pose = "a";
  return Status();
}

}  // namespace smpl
