// The metadata object of docs/file-contract.md as JSON text: written into glTF
// (asset.extras.smpl) and as the sidecar <out>.smpl.json. One serialiser so
// the two cannot drift.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/io/file_io.h"
#include "exporter/asset.h"
#include "exporter/scene_asset.h"

namespace smpl {

// Deterministic JSON (fixed key order, shortest round-trip doubles).
std::string metadataJson(const Asset& asset);

// One file of an output as its sidecar records it.
struct RecordedOutput {
  std::string file;    // base name, escapeInvalidUtf8 (core/utf8.h) of the real name
  uint64_t bytes = 0;  // size
  std::string sha256;  // 64 lowercase hex digits (core/io/sha256.h)
};

// The record of `outputs` (the files written with the sidecar: the output,
// and a .gltf's .bin), in the order given.
std::vector<RecordedOutput> recordOutputs(const std::vector<FileContent>& outputs);

// The sidecar <out>.smpl.json: metadataJson plus, last,
//   "producer": {"hash": producer_hash,          what made the output (request/producer.h)
//                "outputs": [{"file": "walk.glb", "bytes": 123, "sha256": "..."}, ...]}
// "outputs" records every file of the output (recordOutputs; absent when
// `outputs` is empty), so batch mode can tell that the files on disk are still
// the ones this sidecar describes.
std::string sidecarJson(const Asset& asset, const std::string& producer_hash,
                        const std::vector<FileContent>& outputs = {});

// The metadata of a --scene file (scene_asset.h), in the glTF's
// asset.extras.smpl and scenes[0].extras.smpl:
//   {"scene": {"name", "fps", "first_frame", "end_frame",     the shared timeline (source frames)
//              "bodies": [{"name", "track", "first_frame", "end_frame",
//                          "start" (seconds), "hidden_by": "body_scale_step" | "none"}],
//              "camera": {"name", "frames", "yfov", "aspect"}},  when the file has one
//    "bodies": [metadataJson of each body, in the same order]}
std::string sceneMetadataJson(const SceneAsset& scene);

// The sidecar of a --scene file: sceneMetadataJson plus "producer" as sidecarJson.
std::string sceneSidecarJson(const SceneAsset& scene, const std::string& producer_hash,
                             const std::vector<FileContent>& outputs = {});

// The output files a sidecar records; empty when absent or malformed (an old
// or damaged sidecar: rebuild).
std::vector<RecordedOutput> recordedOutputsOf(const std::string& sidecar);

// The producer hash recorded in a sidecar's text; "" when absent or when the
// text is not a JSON object (an old or damaged sidecar: rebuild).
std::string producerHashOf(const std::string& sidecar);

}  // namespace smpl
