// composeScene(): the bodies of a --scene export (one finished Asset per
// track, each baked from its track's first frame at time 0) placed on one
// shared timeline, and the file's camera turned into the export's world.
//
// The timeline runs at the source rate all tracks share, from the earliest
// source frame of any track (or of the camera) to the latest. A body is
// shown over its track's frames [first, end) where the track has a detection
// and hidden elsewhere (before, after, and in a gap of the track): its
// body node's scale is 0 there (STEP keys, SceneBody), which collapses
// the whole skinned mesh to one point in every glTF client (a plain TRS
// scale; KHR_node_visibility is not read by Blender 3.4's importer).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/motions/scene_camera.h"
#include "core/result.h"
#include "exporter/scene_asset.h"

namespace smpl {

// One body to place: its asset (exactly one clip, ClipSource first/end in
// the file's source frames) and the track id it came from.
struct SceneBodyInput {
  Asset asset;
  std::string track;
  // Per source frame from the clip's first (Motion::detected): false where
  // the track has no detection (the clip holds the previous one there); the
  // body is hidden on those frames too. Empty: every frame.
  std::vector<bool> detected = {};
};

// The scene `name` of `bodies` (moved in, in the file's track order) at
// `fps` source frames per second, with `camera` (SceneCamera: OpenCV axes,
// camera-to-world, the file's world) turned by `turn` (the bodies' world
// turn, exporter/animation.h worldTurn) into a glTF camera:
//   rotation = turn * R_cam * diag(1, -1, -1)   (glTF camera x right, y up, looking down -z)
//   position = turn * c
// (glTF 2.0 spec, 3.10 Cameras). Errors (naming `context`): no body, a body
// without exactly one clip, a camera whose rotation and position counts
// differ, a non-finite value or a camera matrix that is not a rotation.
Result<SceneAsset> composeScene(const std::string& name, std::vector<SceneBodyInput> bodies,
                                double fps, const SceneCamera& camera, const Eigen::Matrix3d& turn,
                                const std::string& context);

}  // namespace smpl
