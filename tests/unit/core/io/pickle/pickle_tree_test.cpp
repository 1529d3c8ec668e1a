// Unpickled values -> DataNode (core/io/pickle/pickle_tree.cpp) and the
// pickle heap's expansion bound (PickleLimits::expansion): cycles, depth,
// memo-shared objects, and the hostile case "a 16 KB pickle that shares memo
// objects peaks at 3.5-4 GB before it loads".
#include "core/io/pickle/pickle_tree.h"

#include <gtest/gtest.h>

#include <string>

#include "core/io/pickle/pickle.h"
#include "core/io/pickle/pickle_internal.h"
#include "tests/unit/test_util.h"
#include "tests/unit/tree_expect.h"

namespace smpl {
namespace {

using test::kContainers;
using test::readAll;

template <size_t N>
std::string B(const char (&s)[N]) {
  return std::string(s, N - 1);
}

Result<DataNode> tree(const std::string& bytes, const PickleLimits& limits = PickleLimits()) {
  return parsePickleTree(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "t.pkl",
                         limits);
}

class PickleTreeBudget : public ::testing::Test {
 protected:
  void SetUp() override { setMemoryLimit(256ull << 20); }
  void TearDown() override { setMemoryLimit(0); }
};

// memo_shared.pkl: 16655 bytes; 400 keys share one list of 1000 references
// to one list of 1000 floats: 400 x 8 MB = 3.2 GB as doubles.
TEST_F(PickleTreeBudget, MemoSharedObjectsAreRefusedAt64MiBNotGigabytes) {
  const std::string bytes = readAll(kContainers + "memo_shared.pkl");
  ASSERT_EQ(bytes.size(), 16655u);
  const uint64_t before = memoryCharged();
  const std::string cap =
      "exceeds the limit of 67108864 bytes for an input of 16655 bytes (256 bytes per input byte, "
      "at least 64.0 MiB; beyond that only shared objects repeated many times could need more)";
  // The flat reader of model files and the tree reader both stop at the
  // pickle's own bound (64 MiB), well inside the 256 MiB budget: the error
  // is the pickle's, not the budget's.
  Result<ArrayDict> flat =
      parsePickle(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "memo.pkl");
  ASSERT_FALSE(flat.ok());
  EXPECT_EQ(flat.message(), "memo.pkl: list array of 8000000 bytes " + cap + " (key 'k008')");
  Result<DataNode> t = tree(bytes);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.message(), "t.pkl: list array of 8000000 bytes " + cap + " at ['k008']");
  EXPECT_EQ(memoryCharged(), before);
  // Without the bound, the same 16 KB run on until the memory budget stops
  // them (here at 256 MiB; by default at 4 GiB per pickle).
  PickleLimits unbounded;
  unbounded.expansion = 1ull << 40;
  Result<DataNode> budget = tree(bytes, unbounded);
  ASSERT_FALSE(budget.ok());
  EXPECT_NE(budget.message().find("set --memory-limit"), std::string::npos) << budget.message();
  EXPECT_EQ(memoryCharged(), before);
}

TEST(PickleTree, BoundScalesWithTheInputAndKeepsMaxTotalBytes) {
  PickleLimits limits;
  EXPECT_EQ(pickle::heapByteLimit(limits, 1000), 64ull << 20);         // the floor
  EXPECT_EQ(pickle::heapByteLimit(limits, 1ull << 20), 256ull << 20);  // 256 x 1 MiB
  EXPECT_EQ(pickle::heapByteLimit(limits, 1ull << 30), 4ull << 30);    // max_total_bytes
  EXPECT_EQ(pickle::heapByteLimit(limits, UINT64_MAX), 4ull << 30);    // no overflow
}

TEST(PickleTree, CyclesEndInNoneAndDepthIsBounded) {
  // l = []; l.append(l); {'a': l}
  Result<DataNode> cycle =
      tree(B("\x80\x02}X\x01\x00\x00\x00"
             "a]q\x01h\x01\x61s."));
  ASSERT_TRUE(cycle.ok()) << cycle.message();
  const DataNode* a = cycle->get("a");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(describeNode(*a), "list of 1");
  EXPECT_EQ(a->children[0].kind, DataNode::Kind::None);
  // A dict that contains itself.
  Result<DataNode> self =
      tree(B("\x80\x02}q\x00X\x01\x00\x00\x00"
             "bh\x00s."));
  ASSERT_TRUE(self.ok()) << self.message();
  ASSERT_NE(self->get("b"), nullptr);
  EXPECT_EQ(self->get("b")->kind, DataNode::Kind::None);
  // 40 nested lists around a string: deeper than 32 levels is an error with the path.
  std::string deep = B("\x80\x02");
  for (int i = 0; i < 40; ++i) deep += "]";
  deep += B("X\x01\x00\x00\x00z");
  for (int i = 0; i < 40; ++i) deep += "a";
  deep += ".";
  Result<DataNode> too_deep = tree(deep);
  ASSERT_FALSE(too_deep.ok());
  EXPECT_EQ(too_deep.message().rfind("t.pkl: data nested deeper than 32 levels at [0][0]", 0), 0u)
      << too_deep.message();
  // 100000 nested lists: built iteratively, refused without deep recursion.
  std::string huge = B("\x80\x02");
  huge += std::string(100000, ']') + std::string(99999, 'a') + ".";
  PickleLimits limits;
  limits.max_stack_depth = 200000;
  EXPECT_FALSE(tree(huge, limits).ok());
}

TEST(PickleTree, LeavesOwnTheirDataAndSharedObjectsGiveIndependentLeaves) {
  const std::string bytes = readAll(kContainers + "mixed.pkl");
  Result<DataNode> mixed = tree(bytes);
  ASSERT_TRUE(mixed.ok()) << mixed.message();
  // The tree owns its arrays: each leaf holds a charge covering its data.
  for (const char* key : {"fortran", "big_endian", "names", "object_numbers"}) {
    const Array* a = mixed->leaf(key);
    ASSERT_NE(a, nullptr) << key;
    EXPECT_GE(a->charge.bytes(), a->data.size() * sizeof(double)) << key;
  }
  // {'a': l, 'b': l}, one memoised list l: two equal, independent leaves.
  const std::string shared =
      B("\x80\x02}(X\x01\x00\x00\x00"
        "a(K\x01K\x02lq\x05X\x01\x00\x00\x00"
        "bh\x05u.");
  Result<DataNode> two = tree(shared);
  ASSERT_TRUE(two.ok()) << two.message();
  ASSERT_NE(two->leaf("a"), nullptr);
  ASSERT_NE(two->leaf("b"), nullptr);
  EXPECT_EQ(two->leaf("a")->data, (std::vector<double>{1, 2}));
  EXPECT_EQ(two->leaf("b")->data, (std::vector<double>{1, 2}));
  EXPECT_NE(two->leaf("a")->data.data(), two->leaf("b")->data.data());
}

// A dict of arrays that the memo shares between frames (4D-Humans' held
// entries) reads the same arrays at every reference, not None after the first.
TEST(PickleTree, ArraysUnderASharedDictAreReadAtEveryReference) {
  const std::string bytes = readAll(std::string(SMPL_FIXTURE_DIR) + "/table/shared_subdict.pkl");
  Result<DataNode> t = tree(bytes);
  ASSERT_TRUE(t.ok()) << t.message();
  for (const char* frame : {"a", "b", "c"}) {
    const DataNode* smpl = t->get(frame) ? t->get(frame)->get("smpl") : nullptr;
    ASSERT_TRUE(smpl && smpl->isList() && smpl->children.size() == 1) << frame;
    const Array* orient = smpl->children[0].leaf("global_orient");
    ASSERT_NE(orient, nullptr) << frame;
    EXPECT_EQ(orient->shape, (std::vector<int64_t>{1, 3, 3})) << frame;
    EXPECT_EQ(orient->data[8], 8.0) << frame;
  }
}

TEST(PickleTree, DefaultdictAndNumpySubclassesOnlyInTrees) {
  // collections.defaultdict(dict) with one item, as WHAM's results.
  const std::string dd =
      B("\x80\x02\x63"
        "collections\ndefaultdict\nc__builtin__\ndict\n\x85R"
        "K\x07}X\x01\x00\x00\x00xK\x01ss.");
  Result<DataNode> t = tree(dd);
  ASSERT_TRUE(t.ok()) << t.message();
  ASSERT_NE(t->get("7"), nullptr);
  EXPECT_EQ(t->get("7")->leaf("x")->data, std::vector<double>{1});
  Result<ArrayDict> model =
      parsePickle(reinterpret_cast<const uint8_t*>(dd.data()), dd.size(), "m.pkl");
  ASSERT_FALSE(model.ok());
  EXPECT_EQ(model.message(),
            "m.pkl: refusing pickle global 'collections.defaultdict' (not model data)");
}

}  // namespace
}  // namespace smpl
