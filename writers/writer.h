// One interface for every output format, and the table of formats. A writer
// serialises an Asset to bytes (deterministic: same asset, same bytes); the
// caller writes them atomically.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/byte_span.h"
#include "core/result.h"
#include "exporter/asset.h"
#include "exporter/scene_asset.h"

namespace smpl {

struct WriterOptions {
  bool binary = true;  // glTF: .glb vs .gltf (the format row's `binary`)
  // .gltf only: "" embeds the buffer as a base64 data URI; else the buffer is a
  // separate file of this name beside the output (the JSON's buffer "uri").
  std::string buffer_uri;
  std::string fbx_units = "m";  // FBX: "m" or "cm"
  int fbx_version = 7400;       // FBX: 7400 or 7500
  // FBX: arrays' compression, --fbx-compress-level (the FBX SDK's
  // EXP_FBX_COMPRESS_LEVEL): 0 stored uncompressed, 1..12 libdeflate level.
  int fbx_compress_level = 1;
  // FBX: compression workers (--threads; none = all cores); same bytes for any
  std::optional<int> threads;
  // glTF compact encodings (each optional; see README "Size"):
  double morph_epsilon =
      0.0;             // > 0: drop morph deltas with |d| <= epsilon (metres), sparse accessors
  bool draco = false;  // KHR_draco_mesh_compression for the base mesh (sequential, order kept)
  // --meshopt: EXT_meshopt_compression of the vertex, index, morph and animation views
  bool meshopt = false;
  // --quantize-animation: rotation keys normalised int16, morph weight keys normalised
  // (u)int16 where they fit (core glTF 2.0; writers/gltf/gltf_writer.cpp)
  bool quantize_animation = false;
  std::string bvh_units = "m";  // BVH: "m" or "cm" (--bvh-units), offsets and positions
  // MJCF (writers/mjcf/mjcf_writer.h): --density kg/m^3 in (0, 1e5], --mjcf-joints
  // "hinge" (three per joint) or "ball", --mjcf-motors (a motor per hinge)
  double density = 1000.0;
  std::string mjcf_joints = "hinge";
  bool mjcf_motors = false;
};

struct Writer {
  virtual ~Writer() = default;
  virtual const char* name() const = 0;
  virtual Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const = 0;
  // Bytes of the asset itself (valid while the asset is) that the output
  // holds just before tail[at]: written from where they are, never copied
  // (a GLB's morph weight keys, the largest array of a long clip).
  struct Splice {
    size_t at = 0;
    ByteSpan bytes;
  };
  // The output's bytes and, when options.buffer_uri is set (.gltf), the
  // external buffer's bytes (`buffer`, written beside the output under that
  // name). Formats with one file return serialize() and no buffer.
  struct Files {
    std::string bytes;
    std::string buffer;
    // The output file is bytes + tail (a GLB's BIN chunk, not copied) with the
    // splices (ascending `at`) inserted.
    std::string tail = {};
    std::vector<Splice> splices = {};
    std::vector<ByteSpan> tailParts() const;  // tail and splices in file order
    size_t size() const;                      // of the output file (bytes + tail + splices)
  };
  virtual Result<Files> serializeFiles(const Asset& asset, const WriterOptions& options) const {
    Result<std::string> bytes = serialize(asset, options);
    if (!bytes) return bytes.error();
    return Files{std::move(*bytes), std::string()};
  }
  // Whether the format holds a whole --scene (several skinned bodies on one
  // timeline, a camera): serializeSceneFiles is implemented.
  virtual bool writesScenes() const { return false; }
  // The files of `scene` (scene_asset.h), as serializeFiles. Default: an
  // error naming the format (the request refuses such formats first).
  virtual Result<Files> serializeSceneFiles(const SceneAsset& scene,
                                            const WriterOptions& options) const {
    (void)scene, (void)options;
    return makeError(std::string(name()) + " writer: cannot hold a scene of several bodies");
  }
};

// The writer table: one row per output format, and everything the rest of
// the program knows about a format. The command line reads
// it for --format's choices, the --out extension check, which format-only
// options apply and the usage text; the export request for the writer, the
// WriterOptions container flag, the .gltf buffer file and whether a mesh is
// built at all. Adding a writer is one file under writers/<name>/ and one row
// (docs/architecture.md "Adding a writer").
struct WriterFormat {
  std::string name;                     // "glb": --format value; batch outputs <stem>.<name>
  std::vector<std::string> extensions;  // ".glb": --out FILE ends with one (any case)
  // The format-only options that apply to this format ("--draco"); an option
  // listed by some rows is refused for the others (cli/options.h Applies::Format).
  std::vector<std::string> options;
  // false: a skeleton-only format (e.g. BVH): the request builds no mesh, so
  // no skin is fitted and no morph target computed, and the asset check does
  // not require a mesh (exporter/validate_structure.h).
  bool needs_mesh = true;
  bool binary = true;            // WriterOptions::binary (glTF: GLB, else the JSON .gltf)
  bool external_buffer = false;  // writes <stem>.bin beside the output unless --gltf-embed
  const Writer* writer = nullptr;
  // true: the file holds one animation (BVH); the request refuses a second
  // --motion (request/check_request.cpp). Last: initialisers stay valid.
  bool single_clip = false;
  // false: the file holds no animation; the request refuses --motion and
  // batch mode for it. Last, as above.
  bool animated = true;
  // Non-empty: with a motion, the writer's Files::buffer is written beside
  // the output as <stem> + this suffix (MJCF: ".qpos.npz", the reference
  // motion as MuJoCo qpos; request/run_paths.h gltfBufferPath). Last, as above.
  std::string motion_file = {};
};

// Every row, in usage order (glb, gltf, fbx, bvh, mjcf, usda, usdz; test rows last). Rows stay
// where they are while the table grows (pointers to them remain valid).
const std::deque<WriterFormat>& writerFormats();

// The row whose extension `path` ends with (any case), or null.
const WriterFormat* writerFormatForPath(const std::string& path);

// `bin` with the splices inserted: the whole tail as one string (a .gltf,
// whose buffer is embedded or a file of its own, and serialize()).
std::string withSplices(const std::string& bin, const std::vector<Writer::Splice>& splices);

// The row named `name` (--format), or null.
const WriterFormat* writerFormatByName(const std::string& name);

// The row's writer for `path`'s extension, or null.
const Writer* writerForPath(const std::string& path);

// Every row's extensions for messages: ".glb, .gltf, .fbx or .bvh" (`last`
// joins the final pair; ", " the others).
std::string writerExtensionList(const std::string& last = " or ");

// Test hook: adds `row` to the table while it lives (rows are read without
// a lock: construct and destroy it only while no export runs).
class ScopedWriterFormat {
 public:
  explicit ScopedWriterFormat(WriterFormat row);
  ~ScopedWriterFormat();
  ScopedWriterFormat(const ScopedWriterFormat&) = delete;
  ScopedWriterFormat& operator=(const ScopedWriterFormat&) = delete;
};

// False in builds without meshoptimizer (SMPL_STATIC: Debian ships no static
// libmeshoptimizer); --meshopt is then refused by the request check.
bool meshoptAvailable();
// False in builds without Draco (the Windows build: Debian ships no Draco for
// mingw-w64); --draco is then refused by the request check.
bool dracoAvailable();

}  // namespace smpl
