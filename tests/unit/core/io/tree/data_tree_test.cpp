// The containers entry point (core/io/tree/data_tree.h): every fixture of
// tests/fixtures/make_containers.py read as a tree and compared, node by node,
// with what numpy, torch and joblib say the file holds; sniffing by content;
// the npz member selection; and one-line refusals naming the file.
#include "core/io/tree/data_tree.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/unit/test_util.h"
#include "tests/unit/tree_expect.h"

namespace smpl {
namespace {

using test::expectedTrees;
using test::expectTree;
using test::kContainers;
using test::readAll;

Result<DataNode> readBytes(const std::string& bytes, const std::string& context,
                           const std::vector<std::string>& keys = {}) {
  return readDataTree(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), context, keys);
}

TEST(DataTree, EveryFixtureMatchesWhatPythonWrote) {
  const nlohmann::json& expected = expectedTrees();
  ASSERT_EQ(expected.size(), 27u);
  for (auto it = expected.begin(); it != expected.end(); ++it) {
    Result<DataNode> tree = readDataTree(kContainers + it.key());
    ASSERT_TRUE(tree.ok()) << it.key() << ": " << tree.message();
    expectTree(*tree, it.value(), it.key());
  }
}

TEST(DataTree, SniffsByContentNotByName) {
  const struct {
    const char* file;
    Container container;
  } cases[] = {
      {"wham.pkl", Container::Joblib},
      {"wham_p0.pkl", Container::Joblib},
      {"wham.pkl.z", Container::JoblibCompressed},
      {"wham.pkl.gz", Container::JoblibCompressed},
      {"refused.pkl.bz2", Container::JoblibCompressed},
      {"memo_shared.pkl", Container::Pickle},
      {"gvhmr.pt", Container::TorchZip},
      {"deflated.pt", Container::TorchZip},
      {"romp.npz", Container::Npz},
      {"tram.npy", Container::Npy},
      {"plain.npy", Container::Npy},
      {"mixed.json", Container::Json},
      {"easymocap_000000.json", Container::Json},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    Result<Container> by_path = sniffContainer(kContainers + c.file);
    ASSERT_TRUE(by_path.ok()) << by_path.message();
    EXPECT_EQ(*by_path, c.container) << containerName(*by_path);
    // The same bytes under another name are the same container.
    const std::string bytes = readAll(kContainers + c.file);
    Result<Container> by_bytes = sniffContainer(reinterpret_cast<const uint8_t*>(bytes.data()),
                                                bytes.size(), "renamed.json");
    ASSERT_TRUE(by_bytes.ok());
    EXPECT_EQ(*by_bytes, c.container);
  }
  // Files of the other fixtures: a model .npz, protocol 0 and 2 model pickles.
  const std::string fixtures = SMPL_FIXTURE_DIR;
  EXPECT_EQ(*sniffContainer(fixtures + "/models/smpl_small.npz"), Container::Npz);
  EXPECT_EQ(*sniffContainer(fixtures + "/pickle_cases/p0.pkl"), Container::Pickle);
  EXPECT_EQ(*sniffContainer(fixtures + "/pickle_cases/py2_p2.pkl"), Container::Pickle);
  for (const std::string& bytes :
       {std::string(), std::string("hello"), std::string("\x01\x02", 2)}) {
    Result<Container> c =
        sniffContainer(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "x.bin");
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(*c, Container::Unknown);
  }
}

TEST(DataTree, FormatsRecognisedButNeverReadAreRefusedWhenSniffed) {
  Result<Container> legacy = sniffContainer(kContainers + "legacy.pt");
  ASSERT_FALSE(legacy.ok());
  EXPECT_EQ(legacy.message(),
            "legacy.pt: a legacy torch file: re-save it with torch.save(obj, f) in torch >= 1.6");
  Result<Container> zfile = sniffContainer(kContainers + "refused_zfile.pkl");
  ASSERT_FALSE(zfile.ok());
  EXPECT_NE(zfile.message().find("joblib < 0.9.3"), std::string::npos) << zfile.message();
}

TEST(DataTree, NpzKeysAndMemberSelection) {
  Result<std::vector<std::string>> keys = containerKeys(kContainers + "romp.npz");
  ASSERT_TRUE(keys.ok()) << keys.message();
  EXPECT_EQ(*keys, (std::vector<std::string>{"results", "fps", "names"}));
  // Only the members asked for, in the order asked; absent ones left out.
  Result<DataNode> some = readDataTree(kContainers + "romp.npz", {"names", "absent", "fps"});
  ASSERT_TRUE(some.ok()) << some.message();
  EXPECT_EQ(some->keys, (std::vector<std::string>{"names", "fps"}));
  ASSERT_NE(some->leaf("fps"), nullptr);
  EXPECT_EQ(some->leaf("fps")->data, std::vector<double>{30.0});
  // The same through the bytes overload (NpzArchive::fromBytes).
  Result<DataNode> from_bytes = readBytes(readAll(kContainers + "romp.npz"), "romp.npz", {"fps"});
  ASSERT_TRUE(from_bytes.ok()) << from_bytes.message();
  EXPECT_EQ(from_bytes->keys, std::vector<std::string>{"fps"});
  // Keys of anything else are an error: they are known only once read.
  Result<std::vector<std::string>> torch_keys = containerKeys(kContainers + "gvhmr.pt");
  ASSERT_FALSE(torch_keys.ok());
  EXPECT_EQ(torch_keys.message(),
            "gvhmr.pt: a torch archive, not an .npz: read it with readDataTree");
}

TEST(DataTree, RefusalsAreOneLineNamingTheFileAndTheProblem) {
  const struct {
    const char* file;
    const char* problem;
  } cases[] = {
      {"legacy.pt", "a legacy torch file: re-save it with torch.save(obj, f) in torch >= 1.6"},
      {"evil.pt", "evil.pt/archive/data.pkl: refusing pickle global 'os.system' (not model data)"},
      {"evil_joblib.pkl", "evil_joblib.pkl: refusing pickle global 'os.system' (not model data)"},
      {"missing_key.pt", "no record 'archive/data/7' for storage key '7'"},
      {"stride_oob.pt",
       "torch tensor of size (2,2), stride (3,1) and offset 0 reads past the 4 elements of "
       "storage '0'"},
      {"offset_oob.pt", "size (2,), stride (1,) and offset 3 reads past the 4 elements"},
      {"huge_numel.pt",
       "torch storage '0' declares 1099511627776 elements of 4 bytes; its record has 16 bytes"},
      {"broadcast.pt",
       "strided tensor of 120000000 bytes exceeds the limit of 67108864 bytes for an input of"},
      {"complex.pt", "torch storage type 'torch.ComplexFloatStorage' is not supported"},
      {"script.pt", "a TorchScript archive (torch.jit.save)"},
      {"badorder.pt", "badorder.pt/archive/byteorder: unknown byte order 'middle'"},
      {"refused.pkl.bz2",
       "a bz2-compressed joblib file: decompress it first (python3 -c \"import joblib; "
       "joblib.dump(joblib.load('FILE'), 'FILE', compress=('zlib', 3))\"), or save it with "
       "compress=('zlib', 3)"},
      {"refused.pkl.xz", "an xz-compressed joblib file"},
      {"refused.pkl.lzma", "an lzma-compressed joblib file"},
      {"refused.pkl.lz4", "an lz4-compressed joblib file"},
      {"refused_zfile.pkl", "a joblib file from joblib < 0.9.3"},
      {"memo_shared.pkl", "exceeds the limit of 67108864 bytes for an input of 16655 bytes"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    Result<DataNode> tree = readDataTree(kContainers + c.file);
    ASSERT_FALSE(tree.ok());
    EXPECT_TRUE(tree.message().rfind(std::string(c.file) + ": ", 0) == 0 ||
                tree.message().rfind(std::string(c.file) + "/", 0) == 0)
        << tree.message();
    EXPECT_NE(tree.message().find(c.problem), std::string::npos) << tree.message();
    EXPECT_EQ(tree.message().find('\n'), std::string::npos) << tree.message();
  }
  Result<DataNode> missing = readDataTree("/nonexistent/motion.pkl");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("/nonexistent/motion.pkl"), std::string::npos)
      << missing.message();
  Result<DataNode> unknown = readBytes("hello world", "notes.txt");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.message(),
            "notes.txt: not a container smpl-export reads (it starts with 68 65 6c 6c 6f 20 77 "
            "6f; expected an .npz or torch .pt zip, a pickle or joblib file, an .npy or JSON)");
  Result<DataNode> empty = readBytes("", "empty.pkl");
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.message().find("(it is empty;"), std::string::npos) << empty.message();
}

}  // namespace
}  // namespace smpl
