// parseSettings: argv into the export request, syntax only (values, choices,
// where options apply); ranges and conflicts are the request's
// (check_request_test.cpp).
#include "cli/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "cli/options.h"
#include "request/check_request.h"

namespace smpl {
namespace {

Result<Settings> parse(std::vector<const char*> args) {
  args.insert(args.begin(), "smpl-export");
  return parseSettings(static_cast<int>(args.size()), args.data());
}

TEST(Settings, DefaultsAndValues) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--betas", "1,-2.5,3e-1"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->request.asset.max_influences, 4);
  EXPECT_TRUE(s->request.asset.correctives);
  EXPECT_EQ(s->request.asset.betas, (std::vector<double>{1, -2.5, 0.3}));
  Result<Settings> eq =
      parse({"--model=builtin", "--out=a.gltf", "--max-influences=8", "--correctives=none"});
  ASSERT_TRUE(eq.ok()) << eq.message();
  EXPECT_EQ(eq->request.out, "a.gltf");
  EXPECT_EQ(eq->request.asset.max_influences, 8);
  EXPECT_FALSE(eq->request.asset.correctives);
}

// Only the options that change the bytes enter the producer hash, as given.
TEST(Settings, HashedOptionsFollowTheTable) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--threads", "2", "--name",
                              "x", "-q", "--max-influences", "all"});
  ASSERT_TRUE(s.ok()) << s.message();
  using Option = std::pair<std::string, std::string>;
  EXPECT_EQ(s->request.hashed_options,
            (std::vector<Option>{{"--name", "x"}, {"--max-influences", "all"}}));
  EXPECT_EQ(s->request.asset.max_influences, kAllInfluences);
}

TEST(Settings, FbxCompressLevelAndThreads) {
  Result<Settings> d = parse({"--model", "builtin", "--out", "a.fbx"});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->request.writer.fbx_compress_level, 1);
  EXPECT_FALSE(d->request.writer.threads.has_value());  // all cores
  for (int level : {0, 12, 13}) {                       // 13: the request's range check refuses it
    const std::string v = std::to_string(level);
    Result<Settings> s =
        parse({"--model", "builtin", "--out", "a.fbx", "--fbx-compress-level", v.c_str()});
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(s->request.writer.fbx_compress_level, level);
  }
  Result<Settings> bad =
      parse({"--model", "builtin", "--out", "a.fbx", "--fbx-compress-level", "x"});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(), "--fbx-compress-level: 'x' is not an integer");
  EXPECT_EQ(bad.kind(), ErrorKind::Usage);
  // One export (not batch mode): --threads sets the FBX compression workers.
  Result<Settings> t = parse({"--model", "builtin", "--out", "a.fbx", "--threads", "3"});
  ASSERT_TRUE(t.ok()) << t.message();
  EXPECT_EQ(t->request.writer.threads, 3);
}

// Syntax and where options apply: refused by the parser, before any check of
// values (the request's conflicts and ranges: check_request_test.cpp).
TEST(Settings, RejectsBeforeWork) {
  struct Bad {
    std::vector<const char*> args;
    const char* message;
  };
  const Bad cases[] = {
      {{"--model", "builtin", "--out", "a.glb", "--frobnicate", "1"},
       "unknown option '--frobnicate'"},
      {{"--model", "builtin", "--out", "a.glb", "--frobnicate"}, "unknown option '--frobnicate'"},
      {{"-V"}, "unknown option '-V'"},
      {{"--model", "builtin", "stray", "--out", "a.glb"}, "unexpected argument 'stray'"},
      {{"--model", "builtin", "--out"}, "option --out needs a value"},
      {{"--model", "builtin", "--out", "a.glb", "--betas", "1,x"},
       "--betas: 'x' is not a decimal number"},
      {{"--model", "builtin", "--out", "a.glb", "--betas", "1,nan"},
       "'nan' is not a decimal number"},
      {{"--model", "builtin", "--out", "a.glb", "--fbx-units", "cm"},
       "--fbx-units applies only to .fbx"},
      {{"--model", "builtin", "--out", "a.glb", "--correctives", "some"},
       "expected 'all' or 'none'"},
      {{"--model", "builtin", "--out", "a.glb", "--max-influences", "2.5"}, "is not an integer"},
      {{"--model", "builtin", "--out", "a.glb", "--out", "b.glb"}, "given twice"},
      {{"--model", "builtin", "--out", "a.fbx", "--draco"},
       "--draco applies only to .glb, .gltf output"},
      {{"--model", "builtin", "--out", "a.fbx", "--meshopt"},
       "--meshopt applies only to .glb, .gltf output"},
      {{"--model", "builtin", "--out", "a.fbx", "--motion", "w.npz", "--quantize-animation"},
       "--quantize-animation applies only to .glb, .gltf output"},
      {{"--model", "builtin", "--out", "a.glb", "--frames", "0:10"}, "needs --motion"},
      {{"--model", "builtin", "--out", "a.glb", "--motion", "w.npz", "--frames", "0-10"},
       "--frames: expected A:B, got '0-10'"},
      {{"--model", "builtin", "--out", "a.glb", "--skin-weights", "best"},
       "expected 'truncated' or 'optimized'"},
      {{"--model", "builtin", "--out", "a.glb", "--corrective-weights", "half"},
       "expected 'signed', 'unit' or 'split'"},
      {{"--model", "builtin", "--out", "a.glb", "--gltf-embed"},
       "--gltf-embed applies only to .gltf output"},
      {{"--model", "builtin", "--out-dir", "o"},
       "batch mode needs both --motion-dir and --out-dir"},
  };
  for (const Bad& c : cases) {
    Result<Settings> s = parse(c.args);
    ASSERT_FALSE(s.ok()) << c.message;
    EXPECT_NE(s.message().find(c.message), std::string::npos) << s.message();
    EXPECT_EQ(s.kind(), ErrorKind::Usage);
  }
}

TEST(Settings, SkinWeightsInfluencesAndSplitEncoding) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--skin-weights", "truncated",
                              "--max-influences", "all", "--corrective-weights", "split"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->request.asset.skin_weights, SkinWeightMethod::Truncated);
  EXPECT_EQ(s->request.asset.max_influences, kAllInfluences);
  EXPECT_EQ(s->request.asset.encoding, CorrectiveEncoding::Split);
  Result<Settings> d = parse({"--model", "builtin", "--out", "a.glb", "--max-influences", "12"});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->request.asset.skin_weights, SkinWeightMethod::Optimized);
  EXPECT_EQ(d->request.asset.max_influences, 12);
  Result<Settings> zero = parse({"--model", "builtin", "--out", "a.glb", "--max-influences", "0"});
  ASSERT_FALSE(zero.ok());  // 0 is kAllInfluences inside: the option refuses it, never "all"
  EXPECT_EQ(zero.message(),
            "--max-influences must be between 1 and the model's joints or 'all', got 0");
}

TEST(Settings, MotionFormatAndShardOptions) {
  Result<Settings> s =
      parse({"--model", "builtin", "--motion-dir", "m", "--out-dir", "o", "--source-fps", "59.94",
             "--flat-hand-mean", "--shard", "3/8", "--manifest", "s3.jsonl"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->request.reading.source_fps, 59.94);
  EXPECT_TRUE(s->request.flat_hand_mean);
  EXPECT_EQ(s->shard_index, 3);
  EXPECT_EQ(s->shard_count, 8);
  EXPECT_EQ(s->request.manifest, "s3.jsonl");
  EXPECT_EQ(s->request.motion_dir, "m");
  EXPECT_EQ(s->out_dir, "o");
  struct Bad {
    std::vector<const char*> args;
    const char* message;
  };
  const Bad cases[] = {
      {{"--source-fps", "nan"}, "--source-fps: 'nan' is not a decimal number"},
      {{"--source-fps", "inf"}, "--source-fps: 'inf' is not a decimal number"},
      {{"--shard", "8/8"}, "--shard: expected I/N"},
      {{"--shard", "-1/8"}, "--shard: expected I/N"},
      {{"--shard", "1/0"}, "--shard: expected I/N"},
      {{"--shard", "1"}, "--shard: expected I/N"},
      {{"--shard", "a/b"}, "--shard: expected I/N"},
  };
  for (const Bad& b : cases) {
    std::vector<const char*> args = {"--model", "builtin", "--motion-dir", "m", "--out-dir", "o"};
    args.insert(args.end(), b.args.begin(), b.args.end());
    Result<Settings> r = parse(args);
    ASSERT_FALSE(r.ok()) << b.args[0] << " " << b.args[1];
    EXPECT_NE(r.message().find(b.message), std::string::npos) << r.message();
  }
  for (const char* option : {"--shard", "--manifest"}) {
    Result<Settings> r =
        parse({"--model", "builtin", "--out", "a.glb", "--motion", "w.npz", option, "0/2"});
    ASSERT_FALSE(r.ok()) << option;
    EXPECT_NE(r.message().find("only to batch mode"), std::string::npos) << r.message();
  }
  Result<Settings> still = parse({"--model", "builtin", "--out", "a.glb", "--source-fps", "30"});
  ASSERT_FALSE(still.ok());
  EXPECT_NE(still.message().find("--source-fps needs --motion"), std::string::npos)
      << still.message();
}

// --memory-limit and the range checks of numbers given on the command line.
TEST(SettingsMemory, MemoryLimitIsParsedAndChecked) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--memory-limit", "512M"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->request.memory_limit, 512ull << 20);
  s = parse({"--model", "builtin", "--out", "a.glb"});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->request.memory_limit, 0u);  // the default, chosen at run time
  s = parse({"--model", "builtin", "--out", "a.glb", "--memory-limit", "lots"});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind("--memory-limit: expected a size such as 512M or 4G", 0), 0u)
      << s.message();
  EXPECT_NE(usageText().find("--memory-limit SIZE"), std::string::npos);
}

// One number grammar for every numeric option (core/number_text.h): "0x10",
// "+4", " 4", "inf" are refused by all of them; integers are digits only
// ("1e1", "4.0" refused); decimals may use a fraction and an exponent.
TEST(SettingsNumbers, EveryNumericOptionUsesTheOneGrammar) {
  struct Opt {
    std::vector<const char*> base;  // what the option needs besides itself
    const char* name;
    const char* good;  // a valid value of the option
    bool integer;
  };
  const std::vector<const char*> glb = {"--model", "builtin", "--out", "a.glb"};
  const std::vector<const char*> fbx = {"--model", "builtin", "--out", "a.fbx"};
  const std::vector<const char*> motion = {"--model", "builtin",  "--out",
                                           "a.glb",   "--motion", "m.npz"};
  const std::vector<const char*> batch = {"--model", "builtin",   "--motion-dir",
                                          "m",       "--out-dir", "o"};
  const std::vector<const char*> dmpl = {"--model", "builtin", "--out", "a.glb", "--dmpl", "d.npz"};
  const Opt options[] = {
      {glb, "--betas", "0.5", false},
      {glb, "--expression", "0.5", false},
      {glb, "--max-influences", "8", true},
      {glb, "--corrective-basis", "8", true},
      {glb, "--corrective-epsilon", "1e-3", false},
      {glb, "--shape-keys", "2", true},
      {glb, "--expression-keys", "2", true},
      {dmpl, "--dmpl-count", "2", true},
      {fbx, "--fbx-compress-level", "3", true},
      {glb, "--threads", "2", true},
      {motion, "--source-fps", "3e1", false},
      {motion, "--fps", "2.5e1", false},
      {motion, "--frames", "10:", true},
      {batch, "--shard", "1/2", true},
      {glb, "--memory-limit", "1.5e3M", false},
  };
  for (const Opt& o : options) {
    std::vector<const char*> args = o.base;
    args.push_back(o.name);
    args.push_back(o.good);
    Result<Settings> ok = parse(args);
    EXPECT_TRUE(ok.ok()) << o.name << " " << o.good << ": " << ok.message();
    std::vector<std::string> bad = {"0x10", "+4", " 4", "4 ", "inf", "nan", "0x1p3", "4,"};
    if (o.integer) bad.insert(bad.end(), {"1e1", "4.0"});
    if (std::string(o.name) == "--memory-limit") bad = {"0x10G", "+1G", " 1G", "infG", "1.5e3 M"};
    if (std::string(o.name) == "--frames") bad = {"0x10:", "1e1:", "+1:", ":0x20", " 1:"};
    if (std::string(o.name) == "--shard") bad = {"0x1/2", "1/0x2", "+1/2", "1e0/2", "1/ 2"};
    if (std::string(o.name) == "--betas" || std::string(o.name) == "--expression")
      bad.erase(bad.begin() + 2, bad.begin() + 4);  // blanks around list items are allowed
    for (const std::string& v : bad) {
      args.back() = v.c_str();
      Result<Settings> s = parse(args);
      EXPECT_FALSE(s.ok()) << o.name << " '" << v << "'";
      if (!s.ok()) {
        EXPECT_NE(s.message().find(o.name), std::string::npos) << s.message();
      }
    }
  }
  Result<Settings> spaced = parse({"--model", "builtin", "--out", "a.glb", "--betas", "0.5, -1.2"});
  ASSERT_TRUE(spaced.ok()) << spaced.message();
  EXPECT_EQ(spaced->request.asset.betas, (std::vector<double>{0.5, -1.2}));
  Result<Settings> limit =
      parse({"--model", "builtin", "--out", "a.glb", "--memory-limit", "1e3M"});
  ASSERT_TRUE(limit.ok()) << limit.message();
  EXPECT_EQ(limit->request.memory_limit, 1000ull << 20);
}

}  // namespace
}  // namespace smpl

namespace smpl {
namespace {

// The output (an extension of a writer row) whose format does not take the
// format-only option `name`, or "a.fbx" for the other options.
std::string outputWithout(const std::string& name) {
  for (const WriterFormat& row : writerFormats())
    if (std::find(row.options.begin(), row.options.end(), name) == row.options.end())
      return "a" + row.extensions.front();
  return "";
}

// Every batch-only, motion-only, format-only and mesh-only option of the table is
// refused where it does not apply, with the table's rule in the message.
TEST(OptionTable, EveryRuleIsEnforced) {
  int checked = 0, format_only = 0, mesh_only = 0;
  for (const OptionSpec& o : optionTable()) {
    if (o.applies != Applies::Batch && o.applies != Applies::Format &&
        o.applies != Applies::Motion && o.applies != Applies::Mesh)
      continue;
    const std::string out = o.applies == Applies::Format ? outputWithout(o.name)
                            : o.applies == Applies::Mesh ? "a.bvh"  // a row without a mesh
                                                         : "a.fbx";
    ASSERT_FALSE(out.empty()) << o.name << " applies to every format: it is not format-only";
    format_only += o.applies == Applies::Format;
    mesh_only += o.applies == Applies::Mesh;
    std::vector<const char*> args = {"--model", "builtin", "--out", out.c_str(), o.name};
    const std::map<std::string, std::string> valid = {{"--fbx-units", "cm"},
                                                      {"--fbx-version", "7500"},
                                                      {"--up", "y"},
                                                      {"--root-motion", "keep"},
                                                      {"--frames", "0:1"},
                                                      {"--format", "glb"},
                                                      {"--shard", "0/1"},
                                                      {"--manifest", "m.jsonl"},
                                                      {"--corrective-epsilon", "0.001"},
                                                      {"--track", "all"},
                                                      {"--source-params", "incam"},
                                                      {"--bvh-units", "cm"},
                                                      {"--skeleton-names", "ue5"},
                                                      {"--skin-weights", "truncated"},
                                                      {"--correctives", "none"},
                                                      {"--corrective-refit", "off"},
                                                      {"--corrective-weights", "unit"},
                                                      {"--uv", "none"},
                                                      {"--dmpl-joints", "fixed"},
                                                      {"--mjcf-joints", "ball"},
                                                      {"--mjcf-geoms", "mesh"}};
    const std::string value = valid.count(o.name) ? valid.at(o.name) : "1";
    if (o.value) args.push_back(value.c_str());
    if (std::string(o.name) == "--motion-dir" || std::string(o.name) == "--out-dir")
      continue;  // these start batch mode
    Result<Settings> s = parse(args);
    ASSERT_FALSE(s.ok()) << o.name;
    EXPECT_NE(s.message().find(appliesRule(o)), std::string::npos) << s.message();
    EXPECT_EQ(s.kind(), ErrorKind::Usage);
    ++checked;
  }
  EXPECT_GE(checked, 27);
  EXPECT_EQ(format_only, 15);  // the options the writer rows list
  EXPECT_EQ(mesh_only, 13);    // refused for a format without a mesh
  for (const OptionSpec& o : optionTable()) EXPECT_TRUE(o.help && *o.help) << o.name;
}

}  // namespace
}  // namespace smpl

namespace smpl {
namespace {

// --skeleton-names: the three names into the request; another value, an .xml
// output and a MANO model are refused, naming the option.
TEST(SkeletonNamesOption, ParsedAndRefusedWhereItDoesNotApply) {
  const std::pair<const char*, SkeletonNames> cases[] = {{"smpl", SkeletonNames::Smpl},
                                                         {"mixamo", SkeletonNames::Mixamo},
                                                         {"ue5", SkeletonNames::Ue5}};
  for (const auto& [value, want] : cases) {
    Result<Settings> s = parse({"--model", "builtin", "--out", "a.bvh", "--skeleton-names", value});
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(s->request.asset.skeleton_names, want);
  }
  Result<Settings> bad = parse({"--model", "builtin", "--out", "a.fbx", "--skeleton-names", "ue4"});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(), "--skeleton-names: expected 'smpl', 'mixamo' or 'ue5', got 'ue4'");
  Result<Settings> xml =
      parse({"--model", "builtin", "--out", "a.xml", "--skeleton-names", "mixamo"});
  ASSERT_FALSE(xml.ok());
  EXPECT_NE(xml.message().find("--skeleton-names applies only to .glb, .gltf, .fbx, .bvh"),
            std::string::npos)
      << xml.message();
  ExportRequest r;
  r.asset.skeleton_names = SkeletonNames::Ue5;
  r.asset.max_influences = kAllInfluences;  // the model below has no joints to count
  BodyModel mano;
  mano.kind = ModelKind::Mano;
  mano.name = "MANO_RIGHT";
  EXPECT_EQ(checkRequestForModel(r, {}, mano).message(),
            "--skeleton-names ue5: the model MANO_RIGHT is a MANO hand alone; the Mixamo and UE5 "
            "names are for SMPL, SMPL-H and SMPL-X bodies");
  mano.kind = ModelKind::SmplX;
  EXPECT_TRUE(checkRequestForModel(r, {}, mano).ok());
}

}  // namespace
}  // namespace smpl
