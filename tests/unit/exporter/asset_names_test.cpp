// Names from file names (a motion's stem) need not be UTF-8: exportAsset
// escapes them, the writers' check refuses what is not UTF-8, and the glTF
// and FBX writers then write such an asset (before: the JSON library's
// internal error).
#include "exporter/asset_names.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/demo/demo_body.h"
#include "core/motions/motion.h"
#include "exporter/export_asset.h"
#include "exporter/metadata_json.h"
#include "exporter/validate_asset.h"
#include "writers/writer.h"

namespace smpl {
namespace {

Motion twoFrames(const std::string& name) {
  Motion m;
  m.name = name;
  m.fps = 30;
  m.frames.assign(2, Rotations(24, Eigen::Matrix3d::Identity()));
  m.translation.assign(2, Eigen::Vector3d::Zero());
  return m;
}

TEST(AssetNames, FileNameBytesAreEscapedIntoEveryOutput) {
  const BodyModel model = demoBody();
  ExportOptions o;
  o.name = "mesh\xfe";
  const Motion walk = twoFrames("walk\xff");
  const Motion cafe = twoFrames("caf\xc3\xa9");  // valid UTF-8 stays as it is
  Result<Asset> a = exportAsset(model, o,
                                {{&walk, "walk\xff.npz", AnimationOptions(), nullptr},
                                 {&cafe, "caf\xc3\xa9.npz", AnimationOptions(), nullptr}});
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_EQ(a->animations[0].name, "walk\\xff");
  EXPECT_EQ(a->animations[1].name, "caf\xc3\xa9");
  EXPECT_EQ(a->name, "mesh\\xfe");
  EXPECT_TRUE(checkAssetNames(*a).ok());
  for (const char* ext : {"a.glb", "a.gltf", "a.fbx"}) {
    const Writer* w = writerForPath(ext);
    ASSERT_NE(w, nullptr);
    WriterOptions wo;
    wo.binary = std::string(ext) == "a.glb";
    Result<std::string> bytes = w->serialize(*a, wo);
    ASSERT_TRUE(bytes.ok()) << ext << ": " << bytes.message();
    const bool json = std::string(ext) != "a.fbx";  // JSON doubles the backslash, FBX does not
    EXPECT_NE(bytes->find(json ? "walk\\\\xff" : "walk\\xff"), std::string::npos) << ext;
    EXPECT_EQ(bytes->find("walk\xff"), std::string::npos) << ext;  // the raw byte is gone
  }
  nlohmann::json meta = nlohmann::json::parse(metadataJson(*a));
  EXPECT_EQ(meta["morph_targets"].size(), a->mesh.morph_targets.size());
}

TEST(AssetNames, WritersRefuseNamesThatAreNotUtf8) {
  Result<Asset> a = exportAsset(demoBody(), ExportOptions(), {});
  ASSERT_TRUE(a.ok()) << a.message();
  a->skeleton.names[3] = "spine\xc3";  // as a caller that skipped exportAsset might leave it
  Status st = validateAsset(*a);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "joint name 'spine\\xc3' is not valid UTF-8");
  escapeAssetNames(&*a);
  EXPECT_TRUE(validateAsset(*a).ok());
  EXPECT_EQ(a->skeleton.names[3], "spine\\xc3");
}

}  // namespace
}  // namespace smpl
