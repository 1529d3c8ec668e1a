// qpos rows of a clip (mjcf_qpos.h).
#include "writers/mjcf/mjcf_qpos.h"

#include "core/math/libm.h"

namespace smpl {
namespace {

Eigen::Matrix3d zUpTurn() {  // C: +90 degrees about X, (x, y, z) -> (x, -z, y)
  Eigen::Matrix3d c;
  c << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  return c;
}

void depthFirst(const std::vector<std::vector<int>>& children, int k, std::vector<int>* order) {
  order->push_back(k);
  for (int c : children[size_t(k)]) depthFirst(children, c, order);
}

void pushQuaternion(const Eigen::Matrix3d& r, std::vector<double>* out) {
  Eigen::Quaterniond q(r);
  q.normalize();
  const double s = q.w() < 0 ? -1.0 : 1.0;
  out->insert(out->end(), {s * q.w(), s * q.x(), s * q.y(), s * q.z()});
}

Status checkTracks(const Asset& asset, const AnimationClip& clip, int root) {
  const size_t frames = clip.times.size(), joints = asset.skeleton.names.size();
  if (clip.rotations.size() != joints ||
      (!clip.root_translation.empty() && clip.root_translation.size() != frames))
    return makeError("MJCF writer: clip '" + clip.name + "' tracks do not match its " +
                     std::to_string(frames) + " frames and " + std::to_string(joints) + " joints");
  for (size_t k = 0; k < joints; ++k) {
    if (clip.rotations[k].size() != frames)
      return makeError("MJCF writer: clip '" + clip.name + "' joint " + asset.skeleton.names[k] +
                       " has " + std::to_string(clip.rotations[k].size()) +
                       " rotation keys, expected " + std::to_string(frames));
    if (int(k) == root || clip.joint_translations.empty()) continue;
    const Eigen::Vector3d rest = asset.skeleton.rest_local.row(Eigen::Index(k)).transpose();
    for (const Eigen::Vector3d& p : clip.joint_translations[k])
      if (p != rest)
        return makeError("MJCF writer: joint " + asset.skeleton.names[k] +
                         " moves away from its rest offset (--root-bone, --dmpl-joints); MuJoCo's "
                         "hinge and ball joints hold rotations only");
  }
  return Status();
}

}  // namespace

std::vector<int> mjcfBodyOrder(const Skeleton& s) {
  std::vector<std::vector<int>> children(s.names.size());
  int root = 0;
  for (size_t k = 0; k < s.names.size(); ++k) {
    if (s.parents[k] < 0)
      root = int(k);
    else
      children[size_t(s.parents[k])].push_back(int(k));
  }
  std::vector<int> order;
  if (!s.names.empty()) depthFirst(children, root, &order);
  return order;
}

Eigen::Vector3d mjcfHingeAngles(const Eigen::Matrix3d& r) {
  const double a = libm::atan2(-r(1, 2), r(2, 2));
  const double ca = libm::cos(a), sa = libm::sin(a);
  Eigen::Matrix3d undo_x;  // Rx(-a)
  undo_x << 1, 0, 0, 0, ca, sa, 0, -sa, ca;
  const Eigen::Matrix3d m = undo_x * r;
  return {a, libm::atan2(m(0, 2), m(2, 2)), libm::atan2(m(1, 0), m(1, 1))};
}

Result<MjcfMotion> mjcfMotion(const Asset& asset, const AnimationClip& clip,
                              const std::string& joints) {
  const Skeleton& s = asset.skeleton;
  const std::vector<int> order = mjcfBodyOrder(s);
  if (order.empty()) return makeError("MJCF writer: the skeleton has no joints");
  const int root = order.front();
  if (Status st = checkTracks(asset, clip, root); !st) return st.error();
  const bool hinge = joints == "hinge";
  MjcfMotion m;
  m.nq = 7 + int(order.size() - 1) * (hinge ? 3 : 4);
  m.times = clip.times;
  m.fps = clip.fps;
  for (int k : order)
    if (k == root || !hinge)
      m.joint_names.push_back(s.names[size_t(k)]);
    else
      for (const char* axis : {"_x", "_y", "_z"})
        m.joint_names.push_back(s.names[size_t(k)] + axis);
  const Eigen::Matrix3d c = zUpTurn();
  m.qpos.reserve(clip.times.size() * size_t(m.nq));
  for (size_t f = 0; f < clip.times.size(); ++f) {
    const Eigen::Vector3d p = clip.root_translation.empty()
                                  ? Eigen::Vector3d(s.rest_local.row(root).transpose())
                                  : clip.root_translation[f];
    const Eigen::Vector3d pz = c * p;
    m.qpos.insert(m.qpos.end(), {pz.x(), pz.y(), pz.z()});
    for (int k : order) {
      const Eigen::Matrix3d r =
          c * clip.rotations[size_t(k)][f].cast<double>().normalized().toRotationMatrix() *
          c.transpose();
      if (k == root || !hinge) {
        pushQuaternion(r, &m.qpos);
        continue;
      }
      const Eigen::Vector3d abc = mjcfHingeAngles(r);
      m.qpos.insert(m.qpos.end(), {abc.x(), abc.y(), abc.z()});
    }
  }
  return m;
}

}  // namespace smpl
