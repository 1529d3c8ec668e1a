// The structural half of validateAsset (validate_asset.h): the sizes, indices
// and orderings every writer relies on, with the strictest rule either format
// needs, so the glTF and FBX writers accept exactly the same assets and can
// index without bounds checks. (Before, glTF refused non-increasing key times,
// missing normals and several roots while FBX accepted them.)
#pragma once

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

// Rules, checked in this order (first problem only; K joints, V vertices,
// M influences per vertex, T frames):
//   names: every name valid UTF-8 (asset_names.h);
//   skeleton: K > 0 names, K parents; joint 0 the only root (parent -1) and
//     0 <= parent(j) < j for j > 0 (one skin root, no loops); rest_local and
//     rest_world K x 3 (metres);
//   mesh (none for a skeleton-only asset, Asset::skeleton_only: then no
//     vertices and no morph targets): V > 0; positions, normals V x 3; uvs 0 rows or V x 2;
//     triangles F x 3, F > 0, indices in [0, V); joints and weights V x M, M > 0; joint indices in
//     [0, K); weights >= 0 with a positive sum per vertex; each morph target V x 3, and |delta| <=
//     1 when marked quantized;
//   each animation: T > 0 frames; fps > 0; key times (seconds) >= 0 and
//     strictly increasing as float32 (what the files store); K rotation tracks
//     of T non-zero quaternions; root translations 0 or T; joint translation
//     tracks none or K, each 0 (rest offset) or T; morph weights
//     empty (no weight channel) or T x (#morph targets).
// Error: "<where>: <problem>; expected <rule>", e.g.
//   "animation 'walk': key time of frame 3 (0.1) is not after frame 2 (0.1); expected strictly
//   increasing times".
Status validateAssetStructure(const Asset& asset);

}  // namespace smpl
