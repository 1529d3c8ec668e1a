// Torch tensors inside plain pickles (core/io/pickle/pickle_torch_legacy.cpp):
// storages as torch.storage._load_from_bytes(b), b torch's legacy
// serialization. Fixtures: tests/fixtures/make_legacy_torch.py (files written
// by torch 1.13, and the legacy stream assembled piece by piece, checked there
// against torch's own bytes), and the TRAM and MDM layout fixtures with their
// values as numpy has them (layouts/*/expected/*.npz).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/io/npz.h"
#include "core/io/pickle/pickle.h"
#include "core/io/pickle/pickle_tree.h"
#include "core/memory_budget.h"
#include "tests/unit/test_util.h"
#include "tests/unit/tree_expect.h"

namespace smpl {
namespace {

using test::readAll;

const std::string kLegacy = std::string(SMPL_FIXTURE_DIR) + "/legacy_torch/";
const std::string kLayouts = std::string(SMPL_FIXTURE_DIR) + "/layouts/";

const uint8_t* bytesOf(const std::string& s) { return reinterpret_cast<const uint8_t*>(s.data()); }

Result<DataNode> npyTree(const std::string& file) {
  const std::string bytes = readAll(kLegacy + file);
  return parseNpyTree(bytesOf(bytes), bytes.size(), file);
}

const nlohmann::json& expected() {
  static const nlohmann::json e = nlohmann::json::parse(readAll(kLegacy + "expected.json"));
  return e;
}

class LegacyTorchBudget : public ::testing::Test {
 protected:
  void TearDown() override { setMemoryLimit(0); }
};

TEST(LegacyTorch, TensorsWrittenByTorchAreReadAsTorchHasThem) {
  // np.save of a dict (float32/64/16, int64, bool, a transposed view, two
  // slices of one storage at offsets 2 and 6), and the assembled stream.
  for (const char* file : {"tensors.npy", "assembled.npy"}) {
    Result<DataNode> tree = npyTree(file);
    ASSERT_TRUE(tree.ok()) << tree.message();
    test::expectTree(*tree, expected().at(file), file);
  }
  // pickle.dump (protocols 4 and 2: bytes as _codecs.encode text) and joblib.dump.
  for (const char* file : {"tensor.pkl", "tensor_p2.pkl"}) {
    const std::string bytes = readAll(kLegacy + file);
    Result<DataNode> tree = parsePickleTree(bytesOf(bytes), bytes.size(), file);
    ASSERT_TRUE(tree.ok()) << tree.message();
    test::expectTree(*tree, expected().at(file), file);
  }
  const std::string jb = readAll(kLegacy + "tensor_joblib.pkl");
  Result<DataNode> tree = parseJoblib(bytesOf(jb), jb.size(), "tensor_joblib.pkl");
  ASSERT_TRUE(tree.ok()) << tree.message();
  test::expectTree(*tree, expected().at("tensor_joblib.pkl"), "tensor_joblib.pkl");
}

// Every key of the tree at `file` is a leaf equal to the array numpy saved in `values`.
void expectLeaves(const std::string& file, const std::string& values) {
  SCOPED_TRACE(file);
  const std::string bytes = readAll(kLayouts + file);
  Result<DataNode> tree = parseNpyTree(bytesOf(bytes), bytes.size(), file);
  ASSERT_TRUE(tree.ok()) << tree.message();
  Result<ArrayDict> want = readNpzFile(kLayouts + values);
  ASSERT_TRUE(want.ok()) << want.message();
  std::vector<std::string> keys;
  for (const auto& [key, array] : *want) keys.push_back(key);
  std::vector<std::string> got = tree->keys;
  std::sort(got.begin(), got.end());
  ASSERT_EQ(got, keys);
  for (const auto& [key, array] : *want) {
    SCOPED_TRACE(key);
    const Array* leaf = tree->leaf(key);
    ASSERT_NE(leaf, nullptr);
    EXPECT_EQ(shapeString(leaf->shape), shapeString(array.shape));
    EXPECT_EQ(leaf->dtype, array.dtype);
    EXPECT_EQ(leaf->strings, array.strings);
    ASSERT_EQ(leaf->data.size(), array.data.size());
    for (size_t i = 0; i < array.data.size(); ++i)
      ASSERT_EQ(leaf->data[i], array.data[i]) << "element " << i;
  }
}

TEST(LegacyTorch, TramAndMdmFilesReadWithTheirTensors) {
  // TRAM: every value a tensor (pred_rotmat (28,24,3,3), pred_trans (28,1,3), frame int64).
  expectLeaves("video/tram/seq/hps/hps_track_0.npy", "video/expected/tram_hps_track_0.npz");
  // MDM render_mesh: 'vertices' a strided view padded[0, :, :, :t] of a larger storage.
  expectLeaves("generation/mdm/sample00_rep00_smpl_params.npy",
               "generation/expected/mdm_sample00_rep00_smpl_params.npz");
}

TEST(LegacyTorch, MalformedStreamsAreOneLineErrors) {
  const std::string in = "x.npy: torch.storage._load_from_bytes: ";
  const struct {
    const char* file;
    std::string message;
  } kCases[] = {
      {"bad_truncated.npy", in + "storage '0' has 6 elements of 4 bytes, but only 19 bytes follow"},
      {"bad_count.npy",
       in + "storage '0' has 4611686018427387904 elements of 4 bytes, but only 24 bytes follow"},
      {"bad_mismatch.npy",
       in + "storage '0' is declared with 6 elements of 4 bytes, but its data has 5 of 4"},
      {"bad_magic.npy",
       in + "its bytes do not start with torch's magic number 0x1950a86a20f9469cfc6c"},
      {"bad_version.npy", in + "protocol version is 1000, expected 1001"},
      {"bad_trailing.npy", in + "3 bytes follow the last storage's data"},
      {"bad_missing_key.npy", in + "storage '0' has no data (its key is not in the key list)"},
      {"bad_unknown_key.npy", in + "storage key '9' names no storage"},
      {"bad_twice.npy", in + "storage key '0' is listed twice"},
      {"bad_view.npy", in + "in its storage pickle (at byte 137 of its 263): torch storage '0' is "
                            "a view (view_metadata tuple): not supported"},
      {"bad_object.npy", in + "its pickle holds a int, expected a storage"},
      {"bad_complex.npy",
       in + "in its storage pickle (at byte 137 of its 256): torch storage type "
            "'torch.ComplexFloatStorage' is not supported (complex and quantized tensors are not "
            "motion data)"},
      {"bad_nested.npy", in + "in its storage pickle (at byte 137 of its 542): "
                              "torch.storage._load_from_bytes inside the bytes of another is not "
                              "supported (torch never nests them)"},
      {"bad_global.npy", in + "in its storage pickle (at byte 137 of its 226): refusing pickle "
                              "global 'posix.system' (not model data)"},
      {"bad_bounds.npy",
       "x.npy: torch tensor of size (2,3), stride (3,1) and offset 4 reads past "
       "the 6 elements of storage '0'"},
  };
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.file);
    const std::string bytes = readAll(kLegacy + c.file);
    Result<DataNode> tree = parseNpyTree(bytesOf(bytes), bytes.size(), "x.npy");
    ASSERT_FALSE(tree.ok());
    EXPECT_EQ(tree.message(), c.message);
    EXPECT_EQ(tree.message().find('\n'), std::string::npos);
  }
}

TEST(LegacyTorch, ExpansionBoundAndMemoryBudgetApply) {
  // Stride 0 over 10^7 elements of a 6-element storage: 120 MB from 671 bytes.
  Result<DataNode> broadcast = npyTree("bad_broadcast.npy");
  ASSERT_FALSE(broadcast.ok());
  EXPECT_EQ(
      broadcast.message().rfind("bad_broadcast.npy: strided tensor of 120000000 bytes exceeds "
                                "the limit of 67108864 bytes for an input of 671 bytes",
                                0),
      0u)
      << broadcast.message();
}

TEST(LegacyTorch, RepeatedBytesCountAgainstTheExpansionBound) {
  // The memo names one 64 KiB byte string 2000 times; each _load_from_bytes reads it again.
  const std::string bytes = readAll(kLegacy + "bad_repeated.pkl");
  Result<DataNode> tree = parsePickleTree(bytesOf(bytes), bytes.size(), "bad_repeated.pkl");
  ASSERT_FALSE(tree.ok());
  EXPECT_EQ(tree.message().rfind("bad_repeated.pkl: torch legacy storage bytes of 65", 0), 0u)
      << tree.message();
  EXPECT_NE(tree.message().find("exceeds the limit of 67108864 bytes for an input of"),
            std::string::npos)
      << tree.message();
}

TEST_F(LegacyTorchBudget, TheTensorsAreChargedToTheMemoryBudget) {
  const uint64_t before = memoryCharged();
  setMemoryLimit(before + 2048);  // the pickle's objects fit; not them and the tensors' doubles
  Result<DataNode> tree = npyTree("tensors.npy");
  ASSERT_FALSE(tree.ok());
  EXPECT_NE(tree.message().find("set --memory-limit"), std::string::npos) << tree.message();
  EXPECT_EQ(memoryCharged(), before);
  setMemoryLimit(0);
  EXPECT_TRUE(npyTree("tensors.npy").ok());
}

TEST(LegacyTorch, OnlyTreeReadersRebuildTensors) {
  // Model files keep their allow-list: torch's rebuild function is refused by name.
  const std::string pkl = readAll(kLegacy + "tensor.pkl");
  Result<ArrayDict> model = parsePickle(bytesOf(pkl), pkl.size(), "model.pkl");
  ASSERT_FALSE(model.ok());
  EXPECT_EQ(model.message(),
            "model.pkl: refusing pickle global 'torch._utils._rebuild_tensor_v2' (not model data)");
  // Inside a torch.save archive storages are persistent ids; _load_from_bytes is not allowed.
  const std::string pt = readAll(kLegacy + "in_archive.pt");
  Result<DataNode> archive = parseTorchZip(bytesOf(pt), pt.size(), "in_archive.pt");
  ASSERT_FALSE(archive.ok());
  EXPECT_EQ(archive.message(),
            "in_archive.pt/in_archive/data.pkl: refusing pickle global "
            "'torch.storage._load_from_bytes' (not model data)");
  // Other torch objects stay refused in plain pickles.
  const char kLinear[] =
      "\x80\x02"
      "ctorch.nn.modules.linear\nLinear\n.";
  const std::string linear(kLinear, sizeof(kLinear) - 1);
  Result<DataNode> other = parsePickleTree(bytesOf(linear), linear.size(), "p.pkl");
  ASSERT_FALSE(other.ok());
  EXPECT_EQ(other.message(),
            "p.pkl: refusing pickle global 'torch.nn.modules.linear.Linear': of torch's objects "
            "only tensors are read (convert other objects' tensors with .numpy() before "
            "pickling)");
  // A rebuild whose storage is not a torch storage.
  const char kFake[] =
      "\x80\x02"
      "ctorch._utils\n_rebuild_tensor_v2\n"
      "(K\x00K\x00))\x89}tR.";
  const std::string fake(kFake, sizeof(kFake) - 1);
  Result<DataNode> rebuilt = parsePickleTree(bytesOf(fake), fake.size(), "p.pkl");
  ASSERT_FALSE(rebuilt.ok());
  EXPECT_EQ(rebuilt.message(),
            "p.pkl: torch._utils._rebuild_tensor_v2's storage is a int, expected a torch storage "
            "(a .pt archive's or torch.storage._load_from_bytes)");
}

}  // namespace
}  // namespace smpl
