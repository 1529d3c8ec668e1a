// A whole multi-person result as one file (--scene): one finished Asset per
// track (its own rest mesh, skeleton, corrective targets and clip, built
// exactly as a one-body export builds it), placed on one shared timeline,
// and the camera the tracks were seen from. Writers that hold several
// bodies (writers/writer.h Writer::serializeSceneFiles) translate it; they
// compute nothing about the bodies. Plain data; the timeline is made by
// composeScene (scene_timeline.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "exporter/asset.h"

namespace smpl {

// One body of the scene: the asset holds exactly one clip, whose times start
// at 0 on the body's first frame.
struct SceneBody {
  Asset asset;         // asset.name is the body's name (mesh, mesh node, skin)
  std::string track;   // the track id it was made from ("" for a file without ids)
  double start = 0.0;  // seconds on the scene timeline of the clip's time 0
  int64_t first_frame = 0, end_frame = 0;  // source frames shown, [first, end)
  // Visibility as STEP keys of the body node's scale (1 shown, 0 hidden:
  // outside [first_frame, end_frame) and on frames without a detection):
  // key i holds from times[i] to times[i + 1]. Empty: shown throughout (no
  // scale channel). After the key at 0, keys sit half a source frame before
  // each change, so a player sampling at frame times never lands on a key
  // (float32 times).
  std::vector<double> visibility_times;
  std::vector<float> visibility;
};

// The camera on the scene timeline, in the export's Y-up world (the bodies'
// world turn applied): a glTF camera node, looking down its -Z with +Y up.
struct SceneCameraClip {
  std::vector<double> times;                 // seconds on the scene timeline
  std::vector<Eigen::Vector3d> position;     // metres
  std::vector<Eigen::Quaternionf> rotation;  // camera node to world, unit, sign-continuous
  double yfov = 0.0;                         // radians, > 0
  double aspect = 0.0;                       // width / height; 0: not written
  bool present() const { return !times.empty(); }
};

struct SceneAsset {
  std::string name;                        // the scene's (and its one animation's) name
  double fps = 30.0;                       // the source rate all tracks share
  int64_t first_frame = 0, end_frame = 0;  // source frames the scene spans, [first, end)
  std::vector<SceneBody> bodies;
  SceneCameraClip camera;
  std::vector<std::string> notes;  // for the user, one line each
};

}  // namespace smpl
