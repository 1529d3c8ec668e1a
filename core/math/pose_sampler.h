// Deterministic random poses (axis-angle) for error reports and tests: each
// component uniform in [-scale, scale] radians from a seeded splitmix64, so the
// same seed gives the same poses on every machine (no <random> distributions,
// whose output varies between standard libraries).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace smpl {

std::vector<Eigen::VectorXd> samplePoses(int num_joints, int count, uint64_t seed,
                                         double scale = 0.6);

// The generator behind samplePoses, for other code that needs the same
// machine-independent stream (the demo body's pose set): the next 64-bit
// value of splitmix64, advancing `state`.
uint64_t splitmix64(uint64_t* state);

// Uniform in [0, 1) with 53 random bits, from one splitmix64 step.
double uniform01(uint64_t* state);

}  // namespace smpl
