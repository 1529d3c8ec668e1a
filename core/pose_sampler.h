// Deterministic random poses (axis-angle) for error reports and tests: each
// component uniform in [-scale, scale] radians from a seeded splitmix64, so the
// same seed gives the same poses on every machine (no <random> distributions,
// whose output varies between standard libraries).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace smpl {

std::vector<Eigen::VectorXd> samplePoses(int num_joints, int count, uint64_t seed, double scale = 0.6);

}  // namespace smpl
