#include "writers/fbx/fbx_writer.h"

#include "writers/fbx/fbx_encoder.h"
#include "writers/fbx/fbx_scene.h"

namespace smpl {
namespace {

class FbxWriter : public Writer {
 public:
  const char* name() const override { return "fbx"; }

  Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const override {
    Result<std::vector<FbxNode>> scene = buildFbxScene(asset, options);
    if (!scene) return scene.error();
    return encode(std::move(*scene), options);
  }

  bool writesScenes() const override { return true; }

  Result<Files> serializeSceneFiles(const SceneAsset& scene,
                                    const WriterOptions& options) const override {
    Result<std::vector<FbxNode>> nodes = buildFbxSceneFile(scene, options);
    if (!nodes) return nodes.error();
    Result<std::string> bytes = encode(std::move(*nodes), options);
    if (!bytes) return bytes.error();
    return Files{std::move(*bytes), std::string()};
  }

 private:
  static Result<std::string> encode(std::vector<FbxNode> nodes, const WriterOptions& options) {
    FbxEncodeOptions encode;
    encode.compress_level = options.fbx_compress_level;
    encode.threads = options.threads.value_or(0);
    return encodeFbx(std::move(nodes), static_cast<uint32_t>(options.fbx_version), encode);
  }
};

}  // namespace

const Writer& fbxWriter() {
  static const FbxWriter writer;
  return writer;
}

}  // namespace smpl
