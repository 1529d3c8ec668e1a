// The USD writers (writers/writer.h, rows "usda" `--out body.usda` (or
// `.usd`: USD reads a .usd file as text or binary by its content) and
// "usdz" `--out body.usdz`): the subject as a UsdSkel body for USD tools
// (Omniverse, Isaac Sim, Houdini, Maya, Blender with USD, Apple's Quick Look).
// The .usda is the text layer of usd_layer.h; the .usdz packs that layer as
// body.usda, the package's only file (usdz_archive.h). At most one clip (both
// rows are single_clip); no scenes. docs/usd.md describes the file.
//
//   Result<std::string> text = usdaWriter().serialize(asset, WriterOptions{});
#pragma once

#include "writers/writer.h"

namespace smpl {

const Writer& usdaWriter();
const Writer& usdzWriter();

}  // namespace smpl
