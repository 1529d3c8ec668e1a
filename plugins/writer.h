// One interface for every output format. A writer serialises an Asset to bytes
// (deterministic: same asset, same bytes); the caller writes them atomically.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"
#include "exporter/asset.h"

namespace smpl {

struct WriterOptions {
  bool binary = true;  // glTF: .glb vs .gltf
  // .gltf only: "" embeds the buffer as a base64 data URI; else the buffer is a
  // separate file of this name beside the output (the JSON's buffer "uri").
  std::string buffer_uri;
  std::string fbx_units = "m";  // FBX: "m" or "cm"
  int fbx_version = 7400;       // FBX: 7400 or 7500
  // FBX: arrays' compression, --fbx-compress-level (the FBX SDK's
  // EXP_FBX_COMPRESS_LEVEL): 0 stored uncompressed, 1..12 libdeflate level.
  int fbx_compress_level = 1;
  int threads = 0;  // FBX: compression workers (--threads; 0 = all cores); same bytes for any
  // glTF compact encodings (each optional; see README "Size"):
  double morph_epsilon =
      0.0;  // > 0: drop morph deltas with |d| <= epsilon (metres), sparse accessors
  bool quantize_morphs = false;  // --quantize-morphs; the export job hands it to exportAsset
                                 // (ExportOptions), which marks MorphTarget::quantized: writers
                                 // read the mark, not this flag
  bool draco = false;  // KHR_draco_mesh_compression for the base mesh (sequential, order kept)
};

struct Writer {
  virtual ~Writer() = default;
  virtual const char* name() const = 0;
  virtual Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const = 0;
  // The output's bytes and, when options.buffer_uri is set (.gltf), the
  // external buffer's bytes (`buffer`, written beside the output under that
  // name). Formats with one file return serialize() and no buffer.
  struct Files {
    std::string bytes;
    std::string buffer;
  };
  virtual Result<Files> serializeFiles(const Asset& asset, const WriterOptions& options) const {
    Result<std::string> bytes = serialize(asset, options);
    if (!bytes) return bytes.error();
    return Files{std::move(*bytes), std::string()};
  }
};

// Writers by output file extension (".glb", ".gltf", ".fbx"); null if none.
const Writer* writerForPath(const std::string& path);

}  // namespace smpl
