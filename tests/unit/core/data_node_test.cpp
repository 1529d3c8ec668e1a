// DataNode (core/data_node.h): lookups, the flat view, descriptions, the
// node charge and stacking a list of same-shape arrays.
#include "core/data_node.h"

#include <gtest/gtest.h>

#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::leaf;

DataNode list(std::vector<DataNode> children) {
  DataNode n;
  n.kind = DataNode::Kind::List;
  n.children = std::move(children);
  return n;
}

TEST(DataNode, LookupsFlatViewAndDescriptions) {
  DataNode d;
  d.kind = DataNode::Kind::Dict;
  d.keys = {"pose", "inner", "pose"};
  d.children = {leaf(test::numbers({2}, {1, 2})), list({}), leaf(test::numbers({1}, {3}))};
  ASSERT_NE(d.leaf("pose"), nullptr);
  EXPECT_EQ(d.leaf("pose")->data, std::vector<double>{3});  // the last of a repeated key
  EXPECT_EQ(d.leaf("inner"), nullptr);
  EXPECT_NE(d.get("inner"), nullptr);
  EXPECT_EQ(d.get("absent"), nullptr);
  ArrayDict flat = arraysOf(d);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_EQ(flat["pose"].data, std::vector<double>{3});
  EXPECT_EQ(describeNode(d), "dict with keys 'pose', 'inner', 'pose'");
  EXPECT_EQ(describeNode(d.children[1]), "list of 0");
  EXPECT_EQ(describeNode(d.children[0]), "array (2,)");
  EXPECT_EQ(describeNode(DataNode()), "None");
  DataNode back = nodeOf(std::move(flat));
  EXPECT_EQ(back.keys, std::vector<std::string>{"pose"});
}

TEST(DataNode, StackListJoinsSameShapeLeaves) {
  DataNode l = list({leaf(test::numbers({1, 2}, {1, 2})), leaf(test::numbers({1, 2}, {3, 4}))});
  Result<Array> s = stackList(l, "x.pkl");
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(shapeString(s->shape), "(2,1,2)");
  EXPECT_EQ(s->data, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_GE(s->charge.bytes(), 4 * sizeof(double));
  Result<Array> empty = stackList(list({}), "x.pkl");
  ASSERT_TRUE(empty.ok());
  EXPECT_EQ(shapeString(empty->shape), "(0,)");
  DataNode ragged = list({leaf(test::numbers({2}, {1, 2})), leaf(test::numbers({3}, {1, 2, 3}))});
  EXPECT_EQ(stackList(ragged, "x.pkl").message(),
            "x.pkl: element 1 has shape (3,); element 0 has (2,)");
  DataNode mixed = list({leaf(test::numbers({2}, {1, 2})), DataNode()});
  EXPECT_EQ(stackList(mixed, "x.pkl").message(),
            "x.pkl: element 1 is None, expected a numeric array");
  EXPECT_EQ(stackList(DataNode(), "x.pkl").message(), "x.pkl: None, expected a list of arrays");
}

TEST(DataNode, ChargeNodeHoldsTheNodesBytes) {
  const uint64_t before = memoryCharged();
  {
    DataNode n;
    n.kind = DataNode::Kind::List;
    ASSERT_TRUE(chargeNode(&n, 1000, "x.json").ok());
    EXPECT_EQ(memoryCharged(), before + 1000);
    setMemoryLimit(16ull << 20);
    Status st = chargeNode(&n, 32ull << 20, "x.json");
    setMemoryLimit(0);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.message().rfind("x.json: the tree's nodes would need", 0), 0u) << st.message();
  }
  EXPECT_EQ(memoryCharged(), before);
}

}  // namespace
}  // namespace smpl
