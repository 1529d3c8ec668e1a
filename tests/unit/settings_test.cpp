#include "cli/settings.h"

#include <gtest/gtest.h>

#include <fstream>

namespace smpl {
namespace {

Result<Settings> parse(std::vector<const char*> args) {
  args.insert(args.begin(), "smpl-export");
  return parseSettings(static_cast<int>(args.size()), args.data());
}

TEST(Settings, DefaultsAndValues) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--betas", "1,-2.5,3e-1"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->export_options.max_influences, 4);
  EXPECT_TRUE(s->export_options.correctives);
  EXPECT_TRUE(s->writer_options.binary);
  EXPECT_EQ(s->export_options.betas, (std::vector<double>{1, -2.5, 0.3}));
  Result<Settings> eq = parse({"--model=builtin", "--out=a.gltf", "--max-influences=8", "--correctives=none"});
  ASSERT_TRUE(eq.ok()) << eq.message();
  EXPECT_FALSE(eq->writer_options.binary);
  EXPECT_EQ(eq->export_options.max_influences, 8);
  EXPECT_FALSE(eq->export_options.correctives);
}

TEST(Settings, RejectsBeforeWork) {
  struct Bad { std::vector<const char*> args; const char* message; };
  const Bad cases[] = {
      {{"--model", "builtin", "--out", "a.glb", "--frobnicate", "1"}, "unknown option '--frobnicate'"},
      {{"--out", "a.glb"}, "missing --model"},
      {{"--model", "builtin"}, "missing --out"},
      {{"--model", "builtin", "--out", "a.obj"}, "unknown format"},
      {{"--model", "builtin", "--out", "a.glb", "--betas", "1,x"}, "--betas: 'x' is not a finite number"},
      {{"--model", "builtin", "--out", "a.glb", "--betas", "1,nan"}, "not a finite number"},
      {{"--model", "builtin", "--out", "a.glb", "--betas", "1", "--betas-file", "b.npy"}, "conflict"},
      {{"--model", "builtin", "--out", "a.glb", "--fbx-units", "cm"}, "--fbx-units applies only to .fbx"},
      {{"--model", "builtin", "--out", "a.glb", "--correctives", "some"}, "expected 'all' or 'none'"},
      {{"--model", "builtin", "--out", "a.glb", "--max-influences", "2.5"}, "is not an integer"},
      {{"--model", "builtin", "--out", "a.glb", "--out", "b.glb"}, "given twice"},
      {{"--model", "builtin", "--out"}, "needs a value"},
      {{"--model", "builtin", "--out", "a.glb", "--corrective-basis", "8", "--correctives", "none"}, "conflicts with --correctives none"},
      {{"--model", "builtin", "--out", "a.fbx", "--draco"}, "applies only to glTF"},
      {{"--model", "builtin", "--out", "a.glb", "--frames", "0:10"}, "needs --motion"},
  };
  for (const Bad& c : cases) {
    Result<Settings> s = parse(c.args);
    ASSERT_FALSE(s.ok()) << c.message;
    EXPECT_NE(s.message().find(c.message), std::string::npos) << s.message();
  }
}

TEST(Settings, BetasFileJson) {
  const std::string path = testing::TempDir() + "betas.json";
  std::ofstream(path) << "{\"betas\": [0.5, -1]}";
  Result<std::vector<double>> b = readBetasFile(path);
  ASSERT_TRUE(b.ok()) << b.message();
  EXPECT_EQ(*b, (std::vector<double>{0.5, -1}));
  std::ofstream(path) << "[1, \"x\"]";
  Result<std::vector<double>> bad = readBetasFile(path);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find(path), std::string::npos);
  std::ofstream(path) << "[1, 2";
  EXPECT_FALSE(readBetasFile(path).ok());
}

}  // namespace
}  // namespace smpl
