// Every name in an Asset ends up as text in a file: glTF JSON (node, mesh,
// animation and target names, asset.extras), FBX strings and the sidecar. Some
// come from file names (a motion's stem is its clip name, the model's stem its
// model_name, the DMPL basis' name) or the command line (--name), and those
// bytes need not be UTF-8, which JSON requires (a JSON library throws on them;
// glTF readers refuse them). exportAsset therefore escapes every name
// (escapeInvalidUtf8, core/utf8.h: each stray byte becomes "\xNN",
// deterministically; valid UTF-8, non-ASCII included, is kept), and
// validateAsset refuses an asset whose names are not valid UTF-8, so no writer
// ever sees one.
#pragma once

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

// Escapes, in place, every name of `asset`: mesh name, joint names, morph
// target names, animation names, metadata model_name, corrective and basis
// target names, DMPL basis file and target names, animation tracks.
void escapeAssetNames(Asset* asset);

// Error naming the first name that is not valid UTF-8:
//   "animation name 'walk\xff' is not valid UTF-8"
Status checkAssetNames(const Asset& asset);

}  // namespace smpl
