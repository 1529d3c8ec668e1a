// producerBase: which options and which input files change the producer hash
// (request/producer.h); the command line fills the hashed options
// from its option table's Hashed column.
#include "request/producer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/settings.h"

namespace smpl {
namespace {

std::string hashOf(std::vector<const char*> argv) {
  argv.insert(argv.begin(), "smpl-export");
  Result<Settings> s = parseSettings(static_cast<int>(argv.size()), argv.data());
  EXPECT_TRUE(s.ok()) << s.message();
  if (!s) return "";
  Result<ContentHash> h = producerBase(s->request);
  EXPECT_TRUE(h.ok()) << h.message();
  return h ? h->hex() : "";
}

TEST(Producer, OptionsEnterByTheTablesHashedColumn) {
  const std::string plain = hashOf({"--model", "builtin", "--out", "a.glb"});
  EXPECT_EQ(hashOf({"--model", "builtin", "--out", "b/c.glb", "-q", "--memory-limit", "1G"}),
            plain);                                                                   // Hashed::No
  EXPECT_NE(hashOf({"--model", "builtin", "--out", "a.glb", "--name", "x"}), plain);  // Value
}

// A model folder as released (AMASS-style subfolders): a model file two
// levels down changes the hash when it changes.
TEST(Producer, ModelFolderCoversSubfolders) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("producer_test_" + std::to_string(::getpid()));
  fs::create_directories(dir / "smplh" / "male");
  const fs::path model = dir / "smplh" / "male" / "model.npz";
  std::ofstream(model) << "first";
  const std::string folder = dir.string();
  const std::string before = hashOf({"--model", folder.c_str(), "--out", "a.glb"});
  std::ofstream(model) << "second, longer";
  const std::string after = hashOf({"--model", folder.c_str(), "--out", "a.glb"});
  fs::remove_all(dir);
  EXPECT_NE(before, after);
}

}  // namespace
}  // namespace smpl
