// The binary FBX writer (writers/writer.h): Asset -> FBX 7.4 (or 7.5) bytes
// that Blender, Unity, Maya and Assimp import upright at the right size.
// Scene layout and conventions: fbx_scene.h; byte encoding: fbx_encoder.h.
//
//   Result<std::string> bytes = fbxWriter().serialize(asset, WriterOptions{});
#pragma once

#include "writers/writer.h"

namespace smpl {

const Writer& fbxWriter();

}  // namespace smpl
