// The camera a multi-person result was seen from (PromptHMR's camera_world,
// a world4d .mcs camera): one pose per source frame, in the file's world
// (the same world as the tracks' translations, before any --up turn).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace smpl {

struct SceneCamera {
  // Frame f's camera-to-world rotation and the camera centre in metres:
  // x_world = rotation[f] x_cam + position[f], with OpenCV camera axes
  // (x right, y down, z forward), as the tools write them.
  std::vector<Eigen::Matrix3d> rotation;
  std::vector<Eigen::Vector3d> position;
  int64_t first_frame = 0;  // source frame number of rotation[0], on the tracks' timeline
  double yfov = 0.0;        // vertical field of view in radians; 0 when the file has none
  double aspect = 0.0;      // image width / height; 0 when the file has none
  bool present() const { return !rotation.empty(); }
};

}  // namespace smpl
