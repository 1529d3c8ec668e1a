// glTF 2.0 / GLB writer. Translates an Asset into a tinygltf::Model (one
// buffer, one 4-byte aligned bufferView per accessor) in stages, one file
// each (gltf_stages.h); tinygltf writes the JSON, and the GLB container and
// binary chunk are laid out by gltf_container.cpp (gltf_buffer.h) so the
// buffer is copied once. Morph targets may be sparse or
// quantized (gltf_morphs.h, morph_scales.h), the base mesh Draco-compressed
// (gltf_draco.h), animation outputs normalised integers (--quantize-animation)
// and the views meshopt-compressed (gltf_meshopt.h). Computes nothing about the body: it only
// converts layouts (row-major floats, glTF's v = 1 - v, 4-slot skin sets) and tidies float rounding
// so the Khronos validator reports no warnings.
#include "writers/gltf/gltf_writer.h"

#include <tiny_gltf.h>

#include <string>
#include <utility>

#include "exporter/metadata_json.h"
#include "exporter/validate_asset.h"
#include "writers/gltf/gltf_meshopt.h"
#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace {

using gltf::addAnimation;  // the stages (gltf_stages.h)
using gltf::addMesh;
using gltf::addNodesAndSkin;
using gltf::addSceneContent;
using gltf::glbHead;
using gltf::kBufferPlaceholder;
using gltf::kMetadataPlaceholder;
using gltf::placeholderText;
using gltf::pointBufferAt;
using gltf::requireExtension;
using gltf::serializeJson;
using gltf::splice;
using gltf::spliceMetadata;

// Upper bound of the bytes copied into the buffer, reserved once so appending
// never reallocates. Float morph weight and rotation keys stay in the asset
// (splices) unless meshopt re-encodes them; quantised, they take 2 bytes a
// component.
size_t estimatedBufferBytes(const Asset& a, const WriterOptions& options) {
  const size_t weight_bytes = options.meshopt ? 4 : options.quantize_animation ? 2 : 0;
  const size_t rotation_bytes = options.meshopt ? 16 : options.quantize_animation ? 8 : 16;
  const size_t v = size_t(a.mesh.positions.rows());
  size_t n = v * (12 + 12 + 8 + size_t(a.mesh.joints.cols() + 3) / 4 * 24) +
             size_t(a.mesh.triangles.size()) * 4 + a.skeleton.names.size() * 64 + 64 +
             a.mesh.morph_targets.size() * (v * 16 + 8);
  for (const AnimationClip& c : a.animations)
    n += c.times.size() * (4 + rotation_bytes * c.rotations.size() + 12 +
                           weight_bytes * size_t(c.morph_weights.cols()) + 16);
  return n;
}

constexpr size_t kMaxBufferBytes = 0xF0000000u;  // GLB lengths are uint32

// The asset header every file has; the metadata placeholder in asset.extras.
void startModel(GltfBuild& b, const std::string& exporter_version, size_t reserve,
                const WriterOptions& options) {
  tinygltf::Model& model = b.model;
  b.bin.reserve(reserve);
  b.meshopt = options.meshopt;
  model.asset.version = "2.0";
  const std::string version = exporter_version.empty() ? SMPL_EXPORT_VERSION : exporter_version;
  model.asset.generator = "smpl-export " + version;
  model.asset.extras = tinygltf::Value(
      tinygltf::Value::Object{{"smpl", tinygltf::Value(placeholderText(kMetadataPlaceholder))}});
}

// After the content: meshopt, the buffer's padding, size check and placeholder.
Status finishModel(GltfBuild& b, MeshoptJson* meshopt) {
  tinygltf::Model& model = b.model;
  if (b.meshopt) requireExtension(model, "EXT_meshopt_compression");
  Result<MeshoptJson> compressed = compressMeshoptViews(b);
  if (!compressed) return compressed.error();
  *meshopt = std::move(*compressed);
  b.bin.resize(align4(b.bin.size()), '\0');
  if (b.bufferSize() > kMaxBufferBytes)
    return makeError("glTF writer: buffer of " + std::to_string(b.bufferSize()) +
                     " bytes exceeds the GLB limit of 4 GiB");
  // The bytes stay in b.bin and the splices; tinygltf writes this buffer's JSON with a length
  // of 0 and a placeholder name, replaced by the real length afterwards.
  model.buffers.resize(1);
  model.buffers[0].name = placeholderText(kBufferPlaceholder);
  return Status::success();
}

Status buildModel(const Asset& asset, const WriterOptions& options, GltfBuild& b,
                  MeshoptJson* meshopt) {
  Status st = validateAsset(asset);  // the same rules for every writer (exporter/validate_asset.h)
  if (!st) return st;
  startModel(b, asset.metadata.exporter_version, estimatedBufferBytes(asset, options), options);
  addNodesAndSkin(b, asset);
  st = addMesh(b, asset, options);
  for (const AnimationClip& clip : asset.animations)
    if (st)
      st = addAnimation(b, clip, int(asset.skeleton.names.size()), options.quantize_animation);
  if (!st) return st;
  return finishModel(b, meshopt);
}

Status buildSceneModel(const SceneAsset& scene, const WriterOptions& options, GltfBuild& b,
                       MeshoptJson* meshopt) {
  if (scene.bodies.empty()) return makeError("glTF writer: a scene without bodies");
  size_t reserve = 4096;
  for (const SceneBody& body : scene.bodies)
    reserve += estimatedBufferBytes(body.asset, options) + body.visibility.size() * 16;
  reserve += scene.camera.times.size() * 32;
  startModel(b, scene.bodies.front().asset.metadata.exporter_version, reserve, options);
  if (Status st = addSceneContent(b, scene, options); !st) return st;
  return finishModel(b, meshopt);
}

// The files of a built model with `metadata` over its placeholders.
Result<Writer::Files> filesOf(GltfBuild& b, const MeshoptJson& meshopt, const std::string& metadata,
                              const WriterOptions& options) {
  const size_t buffer_size = b.bufferSize();
  const std::string byte_length = "\"byteLength\":" + std::to_string(buffer_size);
  const bool external = !options.binary && !options.buffer_uri.empty();
  if (!options.binary) {  // a .gltf: the buffer in one piece
    b.bin = withSplices(b.bin, b.splices);
    b.splices.clear();
  }
  if (!options.binary && !external) {  // .gltf, one file: tinygltf embeds the buffer as a data URI
    b.model.buffers[0].name.clear();
    b.model.buffers[0].data.assign(b.bin.begin(), b.bin.end());
    std::string().swap(b.bin);
  }
  Result<std::string> json = serializeJson(b.model, options.binary);
  if (!json) return json.error();
  Status st = spliceMeshoptJson(*json, meshopt, !options.binary);
  if (st) st = spliceMetadata(*json, metadata);
  if (st && options.binary)
    st = splice(*json, "\"byteLength\":0,\"name\":" + std::string(kBufferPlaceholder), byte_length);
  if (st && external) st = pointBufferAt(json.value(), options.buffer_uri, buffer_size);
  if (!st) return st.error();
  if (options.binary)
    return Writer::Files{glbHead(std::move(*json), buffer_size), "", std::move(b.bin),
                         std::move(b.splices)};
  return Writer::Files{std::move(*json), external ? std::move(b.bin) : std::string()};
}

class GltfWriter : public Writer {
 public:
  const char* name() const override { return "glTF"; }

  Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const override {
    WriterOptions embedded = options;
    embedded.buffer_uri.clear();
    Result<Files> files = serializeFiles(asset, embedded);
    if (!files) return files.error();
    return std::move(files->bytes) + withSplices(files->tail, files->splices);
  }

  Result<Files> serializeFiles(const Asset& asset, const WriterOptions& options) const override {
    GltfBuild b;
    MeshoptJson meshopt;
    Status st = buildModel(asset, options, b, &meshopt);
    if (!st) return st.error();
    return filesOf(b, meshopt, metadataJson(asset), options);
  }

  bool writesScenes() const override { return true; }

  Result<Files> serializeSceneFiles(const SceneAsset& scene,
                                    const WriterOptions& options) const override {
    GltfBuild b;
    MeshoptJson meshopt;
    Status st = buildSceneModel(scene, options, b, &meshopt);
    if (!st) return st.error();
    return filesOf(b, meshopt, sceneMetadataJson(scene), options);
  }
};

}  // namespace

const Writer& gltfWriter() {
  static const GltfWriter writer;
  return writer;
}

}  // namespace smpl
