// Rest skeleton and body parts of the demo body: an adult of about 1.73 m in
// SMPL's T-pose (arms straight out along +-X, palms down, facing +Z, feet on
// y = 0). Joint locations follow SMPL's mean template; part radii follow
// average adult proportions. Everything is written for the left side (+X)
// and mirrored.
#include <algorithm>
#include <cmath>

#include "core/demo/demo_body_internal.h"

namespace smpl {
namespace demo {
namespace {

// SMPL's kinematic tree.
const int kParents[kNumJoints] = {-1, 0, 0, 0,  1,  2,  3,  4,  5,  6,  7,  8,
                                  9,  9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21};

struct PartSpec {
  int joint;  // left-side or central joint; its mirror gets the mirrored part
  V3 a, b;
  double ra, rb;
  V3 squash;
};

// Torso and central parts first, then left limbs (mirrored to the right).
const V3 kRound{1, 1, 1};
const V3 kTorso{1, 1, 0.7};
const V3 kFlat{1, 0.42, 1};
const PartSpec kParts[] = {
    {0, {0, 0.95, 0}, {0, 1.05, -0.01}, 0.155, 0.140, kTorso},                     // pelvis: hips
    {3, {0, 1.05, -0.01}, {0, 1.15, -0.005}, 0.140, 0.138, kTorso},                // spine1: waist
    {6, {0, 1.15, -0.005}, {0, 1.27, 0}, 0.138, 0.155, kTorso},                    // spine2: ribs
    {9, {0, 1.27, 0}, {0, 1.34, -0.01}, 0.155, 0.130, kTorso},                     // spine3: chest
    {12, {0, 1.42, -0.015}, {0, 1.53, 0.005}, 0.058, 0.054, kRound},               // neck
    {15, {0, 1.585, 0.02}, {0, 1.645, 0.01}, 0.078, 0.083, {0.9, 1, 1.1}},         // head
    {1, {0.09, 0.86, 0}, {0.10, 0.48, 0}, 0.080, 0.055, kRound},                   // thigh
    {4, {0.10, 0.48, 0}, {0.095, 0.085, -0.035}, 0.055, 0.037, kRound},            // shin
    {7, {0.095, 0.045, -0.05}, {0.105, 0.035, 0.085}, 0.045, 0.038, {1, 0.9, 1}},  // foot
    {10, {0.105, 0.035, 0.085}, {0.105, 0.03, 0.155}, 0.036, 0.026, {1, 0.9, 1}},  // toes
    {13, {0.06, 1.37, -0.015}, {0.17, 1.39, -0.02}, 0.060, 0.055, kRound},         // collar
    {16, {0.17, 1.39, -0.02}, {0.43, 1.39, -0.03}, 0.055, 0.040, kRound},          // upper arm
    {18, {0.43, 1.39, -0.03}, {0.68, 1.39, -0.03}, 0.040, 0.029, kRound},          // forearm
    {20, {0.68, 1.39, -0.03}, {0.765, 1.385, -0.03}, 0.034, 0.043, kFlat},         // palm
    {22, {0.765, 1.385, -0.03}, {0.855, 1.38, -0.03}, 0.043, 0.030, kFlat},        // fingers
};

const V3 kLeftJoints[kNumJoints] = {
    {0, 0.93, 0},         {0.09, 0.86, 0},        {-0.09, 0.86, 0},
    {0, 1.04, -0.012},    {0.10, 0.48, 0},        {-0.10, 0.48, 0},
    {0, 1.16, -0.005},    {0.095, 0.085, -0.035}, {-0.095, 0.085, -0.035},
    {0, 1.23, 0},         {0.105, 0.035, 0.085},  {-0.105, 0.035, 0.085},
    {0, 1.43, -0.015},    {0.07, 1.37, -0.015},   {-0.07, 1.37, -0.015},
    {0, 1.53, 0.005},     {0.17, 1.39, -0.02},    {-0.17, 1.39, -0.02},
    {0.43, 1.39, -0.03},  {-0.43, 1.39, -0.03},   {0.68, 1.39, -0.03},
    {-0.68, 1.39, -0.03}, {0.765, 1.385, -0.03},  {-0.765, 1.385, -0.03}};

V3 mirror(V3 p) { return {-p.x, p.y, p.z}; }

Part makePart(V3 a, V3 b, double ra, double rb, V3 squash) {
  Part p{a, b, ra, rb, squash, (a + b) * 0.5, 0};
  p.reach =
      0.5 * length(b - a) + std::max(ra, rb) * std::max(squash.x, std::max(squash.y, squash.z));
  return p;
}

Rig makeRig() {
  Rig r;
  r.parents.assign(kParents, kParents + kNumJoints);
  r.joints.assign(kLeftJoints, kLeftJoints + kNumJoints);
  r.parts.resize(kNumJoints);
  for (const PartSpec& s : kParts) {
    r.parts[s.joint] = makePart(s.a, s.b, s.ra, s.rb, s.squash);
    // Left joints (odd pairs in SMPL order) have their right twin at index + 1.
    if (s.a.x != 0 || s.b.x != 0)
      r.parts[s.joint + 1] = makePart(mirror(s.a), mirror(s.b), s.ra, s.rb, s.squash);
  }
  return r;
}

// Polynomial smooth minimum (blend width k): joins parts without a crease.
double smoothMin(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

V3 scaled(V3 p, V3 s) { return {p.x / s.x, p.y / s.y, p.z / s.z}; }

// Exact distance to a round cone (sphere-swept segment with linearly varying
// radius), after Inigo Quilez's sdRoundCone; requires |r1 - r2| < |b - a|.
double roundCone(V3 p, V3 a, V3 b, double r1, double r2) {
  const V3 ba = b - a;
  const double l2 = dot(ba, ba), rr = r1 - r2, a2 = l2 - rr * rr, il2 = 1.0 / l2;
  const V3 pa = p - a;
  const double y = dot(pa, ba), z = y - l2;
  const V3 w = pa * l2 - ba * y;
  const double x2 = dot(w, w), y2 = y * y * l2, z2 = z * z * l2;
  const double k = (rr > 0 ? 1.0 : rr < 0 ? -1.0 : 0.0) * rr * rr * x2;
  if ((z > 0 ? 1.0 : z < 0 ? -1.0 : 0.0) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - r2;
  if ((y > 0 ? 1.0 : y < 0 ? -1.0 : 0.0) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - r1;
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - r1;
}

}  // namespace

const Rig& rig() {
  static const Rig r = makeRig();
  return r;
}

double partDistance(const Part& part, V3 p) {
  const V3& s = part.squash;
  const double d = roundCone(scaled(p, s), scaled(part.a, s), scaled(part.b, s), part.ra, part.rb);
  return d * std::min(s.x, std::min(s.y, s.z));
}

double bodyField(const Rig& rig, V3 p) {
  // Blending only parent-child pairs keeps the legs apart at the crotch and
  // the arms off the ribs while every joint gets a smooth transition.
  // Far parts get a lower bound instead of their distance: beyond kFar they
  // cannot change the field near the surface (smoothMin blends within 0.02
  // only) nor its sign, and skipping them makes the field several times cheaper.
  const double kFar = 0.1;
  double d[kNumJoints];
  for (int k = 0; k < kNumJoints; ++k) {
    const Part& part = rig.parts[k];
    const V3& s = part.squash;
    const double ratio = std::min(s.x, std::min(s.y, s.z)) / std::max(s.x, std::max(s.y, s.z));
    const double bound = ratio * (length(p - part.centre) - part.reach);
    d[k] = bound > kFar ? bound : partDistance(part, p);
  }
  double f = d[0];
  for (int k = 1; k < kNumJoints; ++k) f = std::min(f, smoothMin(d[k], d[rig.parents[k]], 0.02));
  return f;
}

V3 closestOnAxis(const Part& part, V3 p, double* t) {
  const V3 ab = part.b - part.a;
  const double s = std::clamp(dot(p - part.a, ab) / dot(ab, ab), 0.0, 1.0);
  if (t) *t = s;
  return part.a + ab * s;
}

}  // namespace demo
}  // namespace smpl
