// joblib files (core/io/pickle/pickle_joblib.cpp, pickle_joblib_file.cpp):
// the fixtures joblib itself wrote (every variant: padded, unpadded, None
// alignment, protocols 0/2/4, zlib, gzip) are compared with numpy in
// data_tree_test; here: the layout details, truncation, byte edits, bombs,
// refusals, and that model pickles still refuse joblib's wrapper.
#include <gtest/gtest.h>

#include <string>

#include "core/io/pickle/pickle.h"
#include "core/io/pickle/pickle_tree.h"
#include "tests/unit/test_util.h"
#include "tests/unit/tree_expect.h"

namespace smpl {
namespace {

using test::kContainers;
using test::readAll;

Result<DataNode> joblib(const std::string& bytes, const std::string& context = "x.pkl") {
  return parseJoblib(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), context);
}

template <size_t N>
std::string B(const char (&s)[N]) {
  return std::string(s, N - 1);
}

class JoblibBudget : public ::testing::Test {
 protected:
  void TearDown() override { setMemoryLimit(0); }
};

TEST(Joblib, WhamTracksAreKeyedByTrackId) {
  Result<DataNode> tree = joblib(readAll(kContainers + "wham.pkl"), "wham.pkl");
  ASSERT_TRUE(tree.ok()) << tree.message();
  EXPECT_EQ(tree->keys, (std::vector<std::string>{"0", "3"}));  // defaultdict(dict), int keys
  const DataNode* track = tree->get("3");
  ASSERT_NE(track, nullptr);
  ASSERT_NE(track->leaf("pose"), nullptr);
  EXPECT_EQ(shapeString(track->leaf("pose")->shape), "(7,72)");
  EXPECT_EQ(track->leaf("pose")->dtype, "<f4");
  EXPECT_EQ(track->leaf("frame_ids")->data, (std::vector<double>{4, 5, 6, 7, 8, 9, 10}));
}

TEST(Joblib, ModelPicklesStillRefuseTheWrapper) {
  // parsePickle (model files) keeps its allow-list: joblib's wrapper is not model data.
  const std::string bytes = readAll(kContainers + "small.pkl");
  Result<ArrayDict> flat =
      parsePickle(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "small.pkl");
  ASSERT_FALSE(flat.ok());
  EXPECT_EQ(flat.message(),
            "small.pkl: refusing pickle global 'joblib.numpy_pickle.NumpyArrayWrapper' (not model "
            "data)");
}

TEST(Joblib, EveryTruncationIsAnError) {
  for (const char* name : {"wham.pkl", "mixed.pkl", "wham_p0.pkl", "wham.pkl.z", "wham.pkl.gz"}) {
    const std::string bytes = readAll(kContainers + name);
    ASSERT_FALSE(bytes.empty());
    // Compressed files inflate each prefix whole: every 13th prefix and the last 64.
    const bool compressed = bytes[0] != '\x80';
    for (size_t n = 0; n < bytes.size(); ++n) {
      if (compressed && n % 13 != 0 && n + 64 < bytes.size()) continue;
      Result<DataNode> r = joblib(bytes.substr(0, n));
      ASSERT_FALSE(r.ok()) << name << " truncated to " << n << " bytes parsed";
      ASSERT_EQ(r.message().rfind("x.pkl: ", 0), 0u) << r.message();
    }
  }
  // Cut right after the padding: the array's 24 bytes are missing.
  const std::string small = readAll(kContainers + "small.pkl");
  const size_t build = small.find(B("K\x10ub"));
  ASSERT_NE(build, std::string::npos);
  const size_t padding = build + 4, data = padding + 1 + static_cast<uint8_t>(small[padding]);
  Result<DataNode> cut = joblib(small.substr(0, data + 8));
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.message(), "x.pkl: joblib array (3,) of dtype '<f8' needs 24 bytes after byte " +
                               std::to_string(data) + "; 8 are left");
}

TEST(Joblib, PaddingIsReadAsJoblibWritesIt) {
  const std::string small = readAll(kContainers + "small.pkl");
  const size_t padding = small.find(B("K\x10ub")) + 4;
  // joblib aligns the data to 16 bytes: the padding length byte says how far.
  EXPECT_EQ((padding + 1 + static_cast<uint8_t>(small[padding])) % 16, 0u);
  Result<DataNode> ok = joblib(small);
  ASSERT_TRUE(ok.ok()) << ok.message();
  EXPECT_EQ(ok->leaf("a")->data, (std::vector<double>{0, 1, 2}));
  // A padding length past the end of the file.
  std::string edited = small;
  edited[padding] = static_cast<char>(250);
  Result<DataNode> past = joblib(edited);
  ASSERT_FALSE(past.ok());
  EXPECT_EQ(past.message(), "x.pkl: joblib array padding of 250 bytes at byte " +
                                std::to_string(padding) + " runs past the end");
  // A padding of 0 shifts the data: the reader then finds the padding bytes'
  // 0xff as elements and the following opcodes misaligned, and says so.
  edited = small;
  edited[padding] = 0;
  Result<DataNode> shifted = joblib(edited);
  ASSERT_FALSE(shifted.ok());
}

TEST(Joblib, OldAndForbiddenGlobalsAreRefusedByName) {
  // joblib < 0.10 kept arrays in separate .npy files (NDArrayWrapper).
  Result<DataNode> old =
      joblib(B("\x80\x02}X\x01\x00\x00\x00"
               "acjoblib.numpy_pickle_compat\nNDArrayWrapper\n)\x81s."));
  ASSERT_FALSE(old.ok());
  EXPECT_EQ(old.message(),
            "x.pkl: an array that joblib < 0.10 stored in a separate file "
            "('joblib.numpy_pickle_compat.NDArrayWrapper'): load it with joblib and dump it again "
            "with joblib >= 0.10");
  Result<DataNode> evil = joblib(readAll(kContainers + "evil_joblib.pkl"), "evil_joblib.pkl");
  ASSERT_FALSE(evil.ok());
  EXPECT_EQ(evil.message(), "evil_joblib.pkl: refusing pickle global 'os.system' (not model data)");
  // Of torch's objects only tensors are read (pickle_torch_legacy_test): a module is refused.
  Result<DataNode> module = joblib(B("\x80\x02\x63torch.nn.modules.linear\nLinear\n."));
  ASSERT_FALSE(module.ok());
  EXPECT_NE(module.message().find("of torch's objects only tensors are read"), std::string::npos)
      << module.message();
}

// A wrapper of dtype object: its array is a whole pickle after the BUILD.
std::string objectWrapper(const std::string& shape) {
  return B("cjoblib.numpy_pickle\nNumpyArrayWrapper\n)\x81}(X\x05\x00\x00\x00"
           "dtypecnumpy\ndtype\nX\x02\x00\x00\x00O8\x89\x88\x87RX\x05\x00\x00\x00shape") +
         shape + "ub";
}

TEST(Joblib, ObjectArraysArePicklesInsideTheStream) {
  // The inline pickle holds a plain int, not an ndarray.
  Result<DataNode> not_array = joblib(B("\x80\x02") + objectWrapper(")") + B("\x80\x02K\x01."));
  ASSERT_FALSE(not_array.ok());
  EXPECT_NE(not_array.message().find("holds a int, expected an ndarray"), std::string::npos)
      << not_array.message();
  // joblib writes that pickle with plain pickle.dump: no wrapper can be inside.
  Result<DataNode> nested =
      joblib(B("\x80\x02") + objectWrapper(")") + B("\x80\x02") + objectWrapper(")") + ".");
  ASSERT_FALSE(nested.ok());
  EXPECT_NE(nested.message().find("a joblib NumpyArrayWrapper inside an object array's pickle"),
            std::string::npos)
      << nested.message();
  // mixed.pkl's object array (a dict, a str, None, a list) comes back as a List.
  Result<DataNode> mixed = joblib(readAll(kContainers + "mixed.pkl"));
  ASSERT_TRUE(mixed.ok()) << mixed.message();
  const DataNode* objects = mixed->get("objects");
  ASSERT_NE(objects, nullptr);
  EXPECT_EQ(describeNode(*objects), "list of 4");
}

TEST_F(JoblibBudget, AZlibBombEndsWithTheBudgetError) {
  const std::string bomb = readAll(kContainers + "bomb.pkl.z");  // 64 MiB of zeros
  setMemoryLimit(16ull << 20);
  const uint64_t before = memoryCharged();
  Result<DataNode> r = joblib(bomb, "bomb.pkl.z");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message().rfind("bomb.pkl.z: inflating the zlib stream would need ", 0), 0u)
      << r.message();
  EXPECT_NE(r.message().find("set --memory-limit"), std::string::npos) << r.message();
  EXPECT_EQ(memoryCharged(), before);
  setMemoryLimit(0);  // with room: the stream stops at the input-scaled bound (its 64 MiB floor)
  r = joblib(bomb, "bomb.pkl.z");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message().rfind("bomb.pkl.z: compressed stream inflates past 64.0 MiB", 0), 0u)
      << r.message();
}

}  // namespace
}  // namespace smpl
