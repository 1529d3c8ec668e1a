// Asset -> binary FBX node tree (the FBX 7.4 document model). The encoder
// (fbx_encoder.h) turns the tree into bytes. Layout, in file order:
// FBXHeaderExtension, FileId, CreationTime, Creator, GlobalSettings,
// Documents, References, Definitions, Objects, Connections, Takes.
//
// Axes and units: geometry stays in model axes (+Y up, right-handed), with
// GlobalSettings saying so (UpAxis Y, FrontAxis +Z, CoordAxis +X). FBX's
// base unit is the centimetre: units "m" writes metres with
// UnitScaleFactor 100, units "cm" scales everything by 100 and writes 1.
// Skeleton: one LimbNode Model per joint (rest local translation, identity
// rotation) under the scene root; the mesh Model is a sibling. Skin clusters,
// BindPose, blend shape channels (one per morph target) and animation
// (Euler XYZ rotation curves per joint, root translation, DeformPercent per
// channel) follow. Ids derive from stable keys, so output is deterministic.
#pragma once

#include <vector>

#include "core/result.h"
#include "exporter/asset.h"
#include "exporter/scene_asset.h"
#include "writers/fbx/fbx_encoder.h"
#include "writers/writer.h"

namespace smpl {

// Fixed header values, so the same asset gives the same bytes.
extern const char kFbxCreationTime[];  // "1970-01-01 10:00:00:000"
extern const char kFbxCreator[];       // "smpl-export"

// Checks the asset's arrays agree in size and index range, then builds the
// top-level nodes. options.fbx_units is "m" or "cm", fbx_version 7400 or 7500.
Result<std::vector<FbxNode>> buildFbxScene(const Asset& asset, const WriterOptions& options);

// A --scene file (exporter/scene_asset.h): every body as a one-body file
// holds it, its objects' names made unique (body node `<body>`, a Null
// parent of its skeleton; mesh `<body>_mesh`; joints, clusters, shapes and
// channels in the namespace `<body>:`), one AnimationStack named after the
// scene whose curves place each body's clip at its start, STEP-like scale
// keys on the body node where it is absent, and the camera (fbx_camera.cpp).
// Errors: no body, bad options, a body failing the asset check (named).
Result<std::vector<FbxNode>> buildFbxSceneFile(const SceneAsset& scene,
                                               const WriterOptions& options);

}  // namespace smpl
