// The demo body's 10 shape directions. Each is a smooth displacement field
// evaluated at the rest vertices, in metres per unit beta, sized so that one
// unit is roughly one standard deviation of adult variation. Joints follow
// through the regressor (J = J_regressor * v_shaped).
//
//   0 height       scale about the floor: +3.6% in Y, +1.2% across (~ +6 cm)
//   1 girth        radial inflation around every part's axis (weight)
//   2 shoulders    arms and shoulder girdle move outward (+2.2 cm per side)
//   3 hips         pelvis widens, legs move outward (+1.8 cm per side)
//   4 leg length   legs stretch, everything above the hips rises (+4.5 cm)
//   5 arm length   arms stretch from the shoulder (+3 cm at the hand)
//   6 head size    head scales about its centre (+8%)
//   7 belly        front of the lower torso bulges (+3.5 cm)
//   8 chest        front of the upper torso bulges (+2.5 cm)
//   9 muscularity  mid-limb bulge of thighs, calves, upper arms and forearms
#include <algorithm>
#include <cmath>

#include "core/demo/demo_body_internal.h"
#include "core/math/libm.h"

namespace smpl {
namespace demo {
namespace {

enum Joint {
  kPelvis = 0,
  kLHip = 1,
  kRHip = 2,
  kSpine1 = 3,
  kLKnee = 4,
  kRKnee = 5,
  kSpine2 = 6,
  kLAnkle = 7,
  kRAnkle = 8,
  kSpine3 = 9,
  kLFoot = 10,
  kRFoot = 11,
  kNeck = 12,
  kLCollar = 13,
  kRCollar = 14,
  kHead = 15,
  kLShoulder = 16,
  kRShoulder = 17,
  kLElbow = 18,
  kRElbow = 19,
  kLWrist = 20,
  kRWrist = 21,
  kLHand = 22,
  kRHand = 23
};

constexpr int kNumShapes = 10;

double clamp1(double v) { return std::clamp(v, -1.0, 1.0); }
double gauss(double v, double sigma) { return libm::exp(-(v / sigma) * (v / sigma)); }
double smoothMin(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

// Sum of a vertex's weights over a set of joints (a soft body-part mask).
double mask(const Eigen::MatrixXd& w, int i, std::initializer_list<int> joints) {
  double m = 0;
  for (int k : joints) m += w(i, k);
  return m;
}

// Offset from each part's axis, blended by skin weight, scaled per part.
V3 radial(const Rig& rig, const Eigen::MatrixXd& w, int i, V3 p, const double* gain, bool bulge) {
  V3 d;
  for (int k = 0; k < kNumJoints; ++k) {
    if (w(i, k) == 0 || gain[k] == 0) continue;
    double t = 0;
    const V3 off = p - closestOnAxis(rig.parts[k], p, &t);
    d = d + off * (w(i, k) * gain[k] * (bulge ? 4 * t * (1 - t) : 1.0));
  }
  return d;
}

V3 displacement(const Rig& rig, const Eigen::MatrixXd& w, int i, V3 p, int shape) {
  static const double kGirth[kNumJoints] = {0.12, 0.10, 0.10, 0.13, 0.08, 0.08, 0.12, 0.04,
                                            0.04, 0.10, 0.03, 0.03, 0.08, 0.08, 0.08, 0.03,
                                            0.10, 0.10, 0.08, 0.08, 0.04, 0.04, 0.03, 0.03};
  static const double kMuscle[kNumJoints] = {0, 0.14, 0.14, 0, 0.16, 0.16, 0,    0,    0, 0, 0, 0,
                                             0, 0,    0,    0, 0.2,  0.2,  0.14, 0.14, 0, 0, 0, 0};
  const double side = p.x > 0 ? 1.0 : -1.0;
  switch (shape) {
    case 0:
      return {0.012 * p.x, 0.036 * p.y, 0.012 * p.z};
    case 1:
      return radial(rig, w, i, p, kGirth, false);
    case 2: {
      const double arm =
          mask(w, i, {kLShoulder, kRShoulder, kLElbow, kRElbow, kLWrist, kRWrist, kLHand, kRHand});
      const double girdle = 0.6 * mask(w, i, {kLCollar, kRCollar}) + 0.2 * w(i, kSpine3);
      return {0.022 * (side * arm + clamp1(p.x / 0.1) * girdle), 0, 0};
    }
    case 3: {
      const double leg =
          mask(w, i, {kLHip, kRHip, kLKnee, kRKnee, kLAnkle, kRAnkle, kLFoot, kRFoot});
      const double pelvis = w(i, kPelvis) + 0.3 * w(i, kSpine1);
      return {0.018 * (clamp1(p.x / 0.015) * leg + clamp1(p.x / 0.12) * pelvis), 0, 0};
    }
    case 4:
      return {0, 0.045 * smoothMin(p.y, 0.86, 0.1) / 0.86, 0};
    case 5:
      return {0.03 * side * std::clamp((std::abs(p.x) - 0.17) / 0.51, 0.0, 1.0), 0, 0};
    case 6:
      return (p - V3{0, 1.615, 0.015}) * (0.08 * (w(i, kHead) + 0.3 * w(i, kNeck)));
    case 7: {
      const double front = std::clamp((p.z + 0.02) / 0.08, 0.0, 1.0);
      return {0, 0,
              0.035 * front * gauss(p.y - 1.02, 0.09) * gauss(p.x, 0.12) *
                  mask(w, i, {kPelvis, kSpine1, kSpine2})};
    }
    case 8: {
      const double front = std::clamp((p.z + 0.02) / 0.08, 0.0, 1.0);
      return {0, 0,
              0.025 * front * gauss(p.y - 1.28, 0.07) * gauss(std::abs(p.x) - 0.08, 0.06) *
                  mask(w, i, {kSpine2, kSpine3})};
    }
    default:
      return radial(rig, w, i, p, kMuscle, true);
  }
}

}  // namespace

Eigen::MatrixXd shapeDirections(const Rig& rig, const Eigen::MatrixXd& vertices,
                                const Eigen::MatrixXd& weights) {
  const int n = static_cast<int>(vertices.rows());
  Eigen::MatrixXd dirs(3 * n, kNumShapes);
  for (int i = 0; i < n; ++i) {
    const V3 p{vertices(i, 0), vertices(i, 1), vertices(i, 2)};
    for (int s = 0; s < kNumShapes; ++s) {
      const V3 d = displacement(rig, weights, i, p, s);
      dirs(3 * i, s) = d.x;
      dirs(3 * i + 1, s) = d.y;
      dirs(3 * i + 2, s) = d.z;
    }
  }
  return dirs;
}

}  // namespace demo
}  // namespace smpl
