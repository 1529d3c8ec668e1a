// --memory-limit and the range checks of numbers given on the command line.
#include <gtest/gtest.h>

#include "cli/settings.h"

namespace smpl {
namespace {

Result<Settings> parse(std::vector<const char*> args) {
  args.insert(args.begin(), "smpl-export");
  return parseSettings(static_cast<int>(args.size()), args.data());
}

TEST(SettingsMemory, MemoryLimitIsParsedAndChecked) {
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--memory-limit", "512M"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->memory_limit, 512ull << 20);
  s = parse({"--model", "builtin", "--out", "a.glb"});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->memory_limit, 0u);  // the default, chosen at run time
  s = parse({"--model", "builtin", "--out", "a.glb", "--memory-limit", "lots"});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind("--memory-limit: expected a size such as 512M or 4G", 0), 0u) << s.message();
  EXPECT_NE(usageText().find("--memory-limit SIZE"), std::string::npos);
}

TEST(SettingsMemory, BetasAndExpressionOnTheCommandLineAreBounded) {
  EXPECT_TRUE(parse({"--model", "builtin", "--out", "a.glb", "--betas", "1000,-1000,0.5"}).ok());
  Result<Settings> s = parse({"--model", "builtin", "--out", "a.glb", "--betas", "0,1e300"});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "--betas: value[1] is 1e+300; expected a finite value with magnitude at most 1000");
  s = parse({"--model", "builtin", "--out", "a.glb", "--expression", "-1001"});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind("--expression: value[0] is -1001", 0), 0u) << s.message();
}

}  // namespace
}  // namespace smpl
