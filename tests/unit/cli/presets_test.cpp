// --preset (cli/presets.h): the bundles set their options, explicit options
// override, options apply only where they can, and bad uses are one-line usage errors.
#include "cli/presets.h"

#include <gtest/gtest.h>

#include "cli/settings.h"

namespace smpl {
namespace {

Result<Settings> parse(std::vector<const char*> args) {
  args.insert(args.begin(), "smpl-export");
  return parseSettings(static_cast<int>(args.size()), args.data());
}

TEST(Presets, WebSetsEverySizeOptionOfGltf) {
  Result<Settings> s =
      parse({"--model", "builtin", "--out", "a.glb", "--motion", "w.npz", "--preset", "web"});
  ASSERT_TRUE(s.ok()) << s.message();
  const ExportRequest& r = s->request;
  EXPECT_TRUE(r.writer.meshopt);
  EXPECT_TRUE(r.asset.quantize_morphs);
  EXPECT_TRUE(r.writer.quantize_animation);
  EXPECT_DOUBLE_EQ(r.writer.morph_epsilon, 1e-5);
  EXPECT_EQ(r.asset.max_influences, 4);
  EXPECT_FALSE(r.writer.draco);
  // The preset is hashed by its name; what it expands to is not given_options.
  EXPECT_EQ(r.hashed_options.back(), (std::pair<std::string, std::string>{"--preset", "web"}));
}

TEST(Presets, ExplicitOptionsOverride) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--max-influences", "8",
                              "--preset", "web", "--corrective-epsilon", "0"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->request.asset.max_influences, 8);
  EXPECT_EQ(s->request.writer.morph_epsilon, 0.0);
  EXPECT_TRUE(s->request.writer.meshopt);
}

TEST(Presets, OptionsApplyOnlyWhereTheyCan) {
  // No motion: no animation to quantise. No correctives: no morph options.
  Result<Settings> s =
      parse({"--model", "builtin", "--out", "a.glb", "--correctives", "none", "--preset", "web"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_FALSE(s->request.writer.quantize_animation);
  EXPECT_FALSE(s->request.asset.quantize_morphs);
  EXPECT_EQ(s->request.writer.morph_epsilon, 0.0);
  EXPECT_TRUE(s->request.writer.meshopt);
  // FBX takes none of the glTF-only options: engine keeps the influences only.
  Result<Settings> fbx =
      parse({"--model", "builtin", "--out", "a.fbx", "--motion", "w.npz", "--preset", "engine"});
  ASSERT_TRUE(fbx.ok()) << fbx.message();
  EXPECT_EQ(fbx->request.writer.morph_epsilon, 0.0);
  EXPECT_EQ(fbx->request.asset.max_influences, 4);
  Result<Settings> archive = parse({"--model", "builtin", "--out", "a.fbx", "--preset", "archive"});
  ASSERT_TRUE(archive.ok()) << archive.message();
  EXPECT_EQ(archive->request.asset.max_influences, kAllInfluences);
  EXPECT_EQ(archive->request.asset.skin_weights, SkinWeightMethod::Truncated);
}

TEST(Presets, BadUsesAreUsageErrors) {
  Result<Settings> fbx = parse({"--model", "builtin", "--out", "a.fbx", "--preset", "web"});
  ASSERT_FALSE(fbx.ok());
  EXPECT_EQ(fbx.message(),
            "--preset web makes glTF files (meshopt, quantised); FBX output has neither: use "
            ".glb, or --preset engine");
  EXPECT_EQ(fbx.kind(), ErrorKind::Usage);
  Result<Settings> unknown = parse({"--model", "builtin", "--out", "a.glb", "--preset", "tiny"});
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.message(), "--preset: expected 'web', 'engine' or 'archive', got 'tiny'");
}

TEST(Presets, HelpListsEveryPresetWithItsOptions) {
  const std::string help = presetsHelp();
  for (const Preset& p : presets()) {
    EXPECT_NE(help.find("\n" + p.name + ": "), std::string::npos) << p.name;
    for (const auto& [name, value] : p.options)
      EXPECT_NE(help.find(name + (value.empty() ? "" : " " + value)), std::string::npos)
          << p.name << ": " << name;
  }
}

}  // namespace
}  // namespace smpl
