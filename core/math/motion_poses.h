// Deterministic synthetic poses that look like motion capture, for training
// and validating fits (skin weights, corrective refit) and for held-out
// reports. Uniform random poses (pose_sampler.h) bend every joint about every
// axis by the same amount; real motion does not: knees and elbows bend one
// way about one axis and far (sitting: hips -1.6 rad, knees +2 rad), spines
// and collars barely move, and joints move together (a stride swings the legs
// in opposite phase and the arms against them; sitting bends hips, knees and
// ankles at once). A fit trained on uniform poses overfits them and can be
// worse than truncation on real motion.
//
// Model: for every joint whose name the authors' tables use (SMPL, SMPL-H,
// SMPL-X, MANO: pelvis, left_hip, ..., left_index1, ...), a range of motion
// per axis of the joint's rest frame (model axes: x the body's left, y up,
// z forward), from the clinical ranges of motion (American Academy of
// Orthopaedic Surgeons, "Joint Motion: Method of Measuring and Recording",
// 1965; see also Roaas & Andersson, Acta Orthop. Scand. 53, 1982) narrowed
// to what everyday captured motion uses. A pose is
//   value = clamp(centre + sum of shared latent activities + noise, lo, hi)
// per joint axis, with the latent activities (each drawn per pose):
//   stride   phase phi, amplitude a: hips flex -/+ a sin(phi) in opposite
//            phase, knees bend in the swing half, shoulders swing against
//            the legs, spine twists with the arms;
//   sit      c: hips flex c * 1.6 rad, knees c * 1.9, ankles c * 0.3, spine c * 0.2;
//   reach    per arm r: shoulder raises and swings forward, elbow bends;
//   grip     per hand g: every finger joint curls together;
//   lean     spine chain bends and twists, split over spine1..3 and neck.
// Noise: uniform, 35% of each axis's half range. Joints named without a
// side (MANO: wrist, index1, ...) get the union of both sides' ranges and
// no shared activity. Unknown joint names get
// +-0.3 rad per axis, independent. The root (pelvis) orientation is uniform
// in +-pi about every axis (it moves the body rigidly). Random numbers come
// from splitmix64 (pose_sampler.h): the same seed gives the same poses on
// every machine.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace smpl {

// `count` poses of 3K axis-angle values (radians, model joint order) for the
// joints named `joint_names` (K names).
std::vector<Eigen::VectorXd> sampleMotionPoses(const std::vector<std::string>& joint_names,
                                               int count, uint64_t seed);

}  // namespace smpl
