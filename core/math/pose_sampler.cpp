#include "core/math/pose_sampler.h"

namespace smpl {

uint64_t splitmix64(uint64_t* state) {
  uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double uniform01(uint64_t* state) { return (splitmix64(state) >> 11) * (1.0 / 9007199254740992.0); }

std::vector<Eigen::VectorXd> samplePoses(int num_joints, int count, uint64_t seed, double scale) {
  uint64_t state = seed;
  std::vector<Eigen::VectorXd> poses(count, Eigen::VectorXd(3 * num_joints));
  for (Eigen::VectorXd& pose : poses)
    for (Eigen::Index i = 0; i < pose.size(); ++i)
      pose[i] = (2.0 * uniform01(&state) - 1.0) * scale;
  return poses;
}

}  // namespace smpl
