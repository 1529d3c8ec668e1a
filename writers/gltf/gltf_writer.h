// glTF 2.0 writer: one skinned mesh with morph targets (pose correctives and
// any shape keys), one node per joint, optional animation clips, and the
// metadata object of docs/file-contract.md in asset.extras.smpl. GLB when
// options.binary, else .gltf with the buffer embedded as a data URI.
//
//   const Writer& w = gltfWriter();
//   Result<std::string> bytes = w.serialize(asset, WriterOptions{});
#pragma once

#include "writers/writer.h"

namespace smpl {

const Writer& gltfWriter();

}  // namespace smpl
