#include "core/math/motion_poses.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "core/joint_names.h"
#include "core/math/libm.h"
#include "core/math/pose_sampler.h"

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct AxisRange {
  double lo, hi;  // radians about the joint's x, y or z axis
};
using JointRange = std::array<AxisRange, 3>;

// Ranges of the left side; the right side mirrors them (x kept, y and z negated).
const std::map<std::string, JointRange>& leftRanges() {
  static const std::map<std::string, JointRange> ranges = {
      {"hip", {{{-1.8, 0.4}, {-0.6, 0.6}, {-0.3, 0.8}}}},
      {"knee", {{{0.0, 2.2}, {-0.15, 0.15}, {-0.1, 0.1}}}},
      {"ankle", {{{-0.5, 0.7}, {-0.3, 0.3}, {-0.3, 0.3}}}},
      {"foot", {{{-0.3, 0.5}, {-0.1, 0.1}, {-0.1, 0.1}}}},
      {"collar", {{{-0.2, 0.2}, {-0.3, 0.3}, {-0.3, 0.4}}}},
      {"shoulder", {{{-0.8, 0.8}, {-1.5, 0.7}, {-1.4, 1.0}}}},
      {"elbow", {{{-0.5, 0.5}, {-2.4, 0.0}, {-0.1, 0.1}}}},
      {"wrist", {{{-0.8, 0.8}, {-0.5, 0.5}, {-1.0, 1.0}}}},
      {"hand", {{{-0.3, 0.3}, {-0.3, 0.3}, {-0.5, 0.5}}}},
      {"finger", {{{-0.15, 0.15}, {-0.2, 0.2}, {-1.4, 0.2}}}},
      {"thumb", {{{-0.5, 0.5}, {-0.6, 0.6}, {-0.5, 0.5}}}},
      {"eye", {{{-0.3, 0.3}, {-0.4, 0.4}, {-0.1, 0.1}}}},
  };
  return ranges;
}

// Unsided joints.
const std::map<std::string, JointRange>& centralRanges() {
  static const std::map<std::string, JointRange> ranges = {
      {"spine1", {{{-0.3, 0.6}, {-0.3, 0.3}, {-0.25, 0.25}}}},
      {"spine2", {{{-0.2, 0.4}, {-0.3, 0.3}, {-0.2, 0.2}}}},
      {"spine3", {{{-0.2, 0.3}, {-0.3, 0.3}, {-0.2, 0.2}}}},
      {"neck", {{{-0.5, 0.6}, {-0.6, 0.6}, {-0.4, 0.4}}}},
      {"head", {{{-0.4, 0.4}, {-0.5, 0.5}, {-0.3, 0.3}}}},
      {"jaw", {{{0.0, 0.4}, {-0.1, 0.1}, {-0.1, 0.1}}}},
  };
  return ranges;
}

// What a joint is: its class in the tables above and its side (+1 left,
// -1 right, 0 central or unknown).
struct JointClass {
  std::string kind;  // table key; "" unknown
  int side = 0;
  int digit = 0;  // finger segment 1..3 (0: not a finger)
};

JointClass classify(const std::string& raw) {
  const std::string name = canonicalJointName(raw);
  JointClass c;
  std::string rest = name;
  if (name.rfind("left_", 0) == 0) c.side = 1, rest = name.substr(5);
  if (name.rfind("right_", 0) == 0) c.side = -1, rest = name.substr(6);
  if (c.side == 0 && centralRanges().count(name)) {
    c.kind = name;
    return c;
  }
  if (rest.rfind("eye", 0) == 0) rest = "eye";
  for (const char* finger : {"index", "middle", "pinky", "ring", "thumb"})
    if (rest.rfind(finger, 0) == 0 && rest.size() == std::string(finger).size() + 1) {
      c.digit = rest.back() - '0';
      rest = std::string(finger) == "thumb" ? "thumb" : "finger";
    }
  if (leftRanges().count(rest)) c.kind = rest;
  return c;
}

// A sided joint without a side in its name (MANO's wrist, index1, ...: a
// file holds either hand) gets the union of both sides' ranges.
JointRange rangeOf(const JointClass& c) {
  if (c.kind.empty()) return {{{-0.3, 0.3}, {-0.3, 0.3}, {-0.3, 0.3}}};
  if (centralRanges().count(c.kind)) return centralRanges().at(c.kind);
  JointRange r = leftRanges().at(c.kind);
  for (int a = 1; a < 3; ++a) {
    const AxisRange mirrored{-r[a].hi, -r[a].lo};
    if (c.side < 0) r[a] = mirrored;
    if (c.side == 0) r[a] = {std::min(r[a].lo, mirrored.lo), std::max(r[a].hi, mirrored.hi)};
  }
  return r;
}

// The latent activities of one pose (see the header).
struct Activities {
  double stride_phase = 0.0, stride = 0.0, sit = 0.0, lean_x = 0.0, lean_y = 0.0, lean_z = 0.0;
  double reach[2] = {0.0, 0.0}, grip[2] = {0.0, 0.0};  // [left, right]
};

Activities drawActivities(uint64_t* state) {
  Activities a;
  a.stride_phase = 2.0 * kPi * uniform01(state);
  a.stride = uniform01(state) < 0.6 ? uniform01(state) : 0.0;
  a.sit = uniform01(state) < 0.35 ? uniform01(state) : 0.0;
  a.lean_x = 2.0 * uniform01(state) - 1.0;
  a.lean_y = 2.0 * uniform01(state) - 1.0;
  a.lean_z = 2.0 * uniform01(state) - 1.0;
  for (int s = 0; s < 2; ++s) {
    a.reach[s] = uniform01(state) < 0.5 ? uniform01(state) : 0.0;
    a.grip[s] = uniform01(state);
  }
  return a;
}

// The shared part of joint `c`'s rotation for activities `a` (radians, x y z).
Eigen::Vector3d shared(const JointClass& c, const Activities& a) {
  const double s = libm::sin(a.stride_phase) * c.side;  // left and right in opposite phase
  const int hand = c.side > 0 ? 0 : 1;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  const std::string& k = c.kind;
  if (k == "hip") v.x() = -0.6 * a.stride * s - 1.6 * a.sit;
  if (k == "knee") v.x() = 1.0 * a.stride * std::max(0.0, s) + 1.9 * a.sit;
  if (k == "ankle") v.x() = 0.3 * a.stride * s + 0.3 * a.sit;
  if (k == "shoulder") {
    v.y() = c.side * (0.4 * a.stride * s - 1.0 * a.reach[hand]);
    v.z() = c.side * (0.9 * a.reach[hand] - 0.9 * (1.0 - a.reach[hand]));
  }
  if (k == "elbow") v.y() = -c.side * (0.3 * a.stride + 1.3 * a.reach[hand]);
  if (k == "finger") v.z() = -c.side * 1.1 * a.grip[hand] * (c.digit == 1 ? 0.8 : 1.0);
  if (k.rfind("spine", 0) == 0 || k == "neck") {
    v.x() = 0.12 * a.lean_x + 0.07 * a.sit;
    v.y() = 0.12 * a.lean_y + 0.05 * a.stride * libm::sin(a.stride_phase);
    v.z() = 0.08 * a.lean_z;
  }
  return v;
}

}  // namespace

std::vector<Eigen::VectorXd> sampleMotionPoses(const std::vector<std::string>& joint_names,
                                               int count, uint64_t seed) {
  const int k = static_cast<int>(joint_names.size());
  std::vector<JointClass> classes;
  std::vector<JointRange> ranges;
  for (const std::string& name : joint_names) {
    classes.push_back(classify(name));
    ranges.push_back(rangeOf(classes.back()));
  }
  uint64_t state = seed;
  std::vector<Eigen::VectorXd> poses(std::max(0, count), Eigen::VectorXd::Zero(3 * k));
  for (Eigen::VectorXd& pose : poses) {
    const Activities a = drawActivities(&state);
    for (int j = 0; j < k; ++j) {
      const Eigen::Vector3d common = j == 0 ? Eigen::Vector3d::Zero() : shared(classes[j], a);
      for (int axis = 0; axis < 3; ++axis) {
        const double u = 2.0 * uniform01(&state) - 1.0;
        if (j == 0) {  // the root: any orientation
          pose[axis] = kPi * u;
          continue;
        }
        const AxisRange r = ranges[size_t(j)][size_t(axis)];
        const double half = 0.5 * (r.hi - r.lo);
        const double centre = std::clamp(0.0, r.lo, r.hi);  // rest, if inside the range
        const double value = centre + common[axis] + 0.35 * half * u;
        pose[3 * j + axis] = std::clamp(value, r.lo, r.hi);
      }
    }
  }
  return poses;
}

}  // namespace smpl
