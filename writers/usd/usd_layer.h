// The asset as one USD text layer (.usda): a UsdSkel body, metres, Y up. The
// USD writer (usd_writer.h) writes it as a .usda file or packs it into a
// .usdz. docs/usd.md describes the file; in short:
//
//   #usda 1.0 (defaultPrim = "Body", metersPerUnit = 1, upAxis = "Y",
//              timeCodesPerSecond = fps, startTimeCode 0, endTimeCode T - 1,
//              customLayerData { string smpl_export = <metadata JSON> })
//   def SkelRoot "Body"
//     def Skeleton "Skeleton": joints (path tokens "pelvis/left_hip/...", in
//       skeleton order), jointNames (the bare names), bindTransforms (world:
//       a translation by the rest joint J_k), restTransforms (local: a
//       translation by J_k - J_parent), rel skel:animationSource
//       def SkelAnimation "Motion": joints, blendShapes (every morph target),
//         rotations (quatf, local), translations (float3, local), scales
//         (half3, 1), blendShapeWeights: time samples at time code f = frame
//         f of the clip, or without a clip one default value (the rest pose:
//         identity rotations, rest translations, the targets' rest weights)
//     def Mesh "Mesh": points, normals, primvars:st (with UVs), triangles,
//       extent, primvars:skel:jointIndices / jointWeights (elementSize M,
//       vertex), primvars:skel:geomBindTransform identity, skel:blendShapes,
//       rel skel:blendShapeTargets, rel skel:skeleton
//       def BlendShape "<target>": offsets (metres) at pointIndices (the
//         vertices whose delta is not exactly zero)
//
// The UsdSkel evaluation of this layer is the file contract's math: blend
// shapes add weight * offset to the points before skinning (as glTF morph
// targets), and the skinning transform of joint k is
// inverse(bindTransform_k) * jointWorld_k (UsdSkel "Schemas In-Depth",
// openusd.org/release/api/_usd_skel__schemas.html).
//
// Errors: more than one clip, a joint or morph target name that is not a USD
// identifier ([A-Za-z_][A-Za-z0-9_]*), duplicate names, a parent after its
// child, a quantized morph target, key times off the fps grid, and
// validateAsset's.
#pragma once

#include <string>

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

Result<std::string> usdaLayer(const Asset& asset);

}  // namespace smpl
