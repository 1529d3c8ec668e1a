// The glTF parts of a Meshcapade scene file (.mcs, motion_mcs.h): buffers as
// base64 data URIs, buffer views, float accessors, and the animated camera
// node, read from the file's JSON tree (core/io/tree/json_tree.h). Bounded:
// every index, offset, count and declared length is checked against what the
// file really holds before anything is decoded or allocated.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/data_node.h"
#include "core/motions/scene_camera.h"
#include "core/result.h"

namespace smpl {
namespace mcs {

// The bytes of bufferViews[view]: its buffer's data URI decoded (base64),
// then [byteOffset, byteOffset + byteLength). Errors name `context` and the
// part: "x.mcs: buffer 1: base64 data is truncated (...)", "x.mcs: buffer 0
// declares 1099511627776 bytes; its data URI holds 2048".
Result<std::vector<uint8_t>> bufferViewBytes(const DataNode& root, int64_t view,
                                             const std::string& context);

// accessors[index] as count x `components` little-endian float32 values
// (componentType 5126; SCALAR 1, VEC3 3, VEC4 4), widened, row-major.
Result<std::vector<double>> accessorFloats(const DataNode& root, int64_t index, int components,
                                           const std::string& context);

// The scene camera (scene_camera.h) of the first node with a `camera`: its
// translation and rotation channels (animations[*].channels targeting it;
// LINEAR samplers, times in seconds) sampled at every frame f of the timeline
// whose time f / fps lies within the keys (positions interpolated linearly,
// rotations by slerp, keys hit exactly), or the node's static pose for
// `num_frames` frames. glTF cameras look down -z with y up: rotation =
// R_node diag(1,-1,-1) gives the OpenCV axes of SceneCamera (the inverse of
// PromptHMR's mcs_export_cam.py add_camera_animation: R_node = Rcw^T cv_to_gltf).
// yfov and aspect from cameras[node.camera].perspective. No camera node: an
// empty camera. `notes` gets what was assumed, and names a transform on the
// camera node's parent as ignored (PromptHMR's RootNode has none).
Result<SceneCamera> readCamera(const DataNode& root, double fps, int64_t num_frames,
                               const std::string& context, std::vector<std::string>* notes);

// Small accessors of the JSON tree, shared with motion_mcs.cpp.
const DataNode* element(const DataNode* list, int64_t i);  // a List's child i, or nullptr
// A non-negative integer member `key` of a Dict (absent: `fallback`, or an
// error when fallback < 0). Errors: "<context>: 'key' is not a non-negative integer".
Result<int64_t> integer(const DataNode& dict, const char* key, int64_t fallback,
                        const std::string& context);

}  // namespace mcs
}  // namespace smpl
