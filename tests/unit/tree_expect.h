// Compares a DataNode tree with its description in the containers fixture's
// expected.json (tests/fixtures/make_containers.py: describe(), an
// independent statement of the conversion rules, with values computed by
// numpy and torch).
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/data_node.h"
#include "tests/unit/test_util.h"

namespace smpl::test {

inline const std::string kContainers = std::string(SMPL_FIXTURE_DIR) + "/containers/";

inline const nlohmann::json& expectedTrees() {
  static const nlohmann::json expected =
      nlohmann::json::parse(readAll(kContainers + "expected.json"));
  return expected;
}

inline const char* kindName(DataNode::Kind kind) {
  switch (kind) {
    case DataNode::Kind::None:
      return "none";
    case DataNode::Kind::Array:
      return "array";
    case DataNode::Kind::Dict:
      return "dict";
    case DataNode::Kind::List:
      return "list";
  }
  return "?";
}

// Every node's kind, every dict's keys in order, every list's length, every
// leaf's shape, dtype and exact values (or strings). `where`: the path so far.
inline void expectTree(const DataNode& node, const nlohmann::json& e, const std::string& where) {
  SCOPED_TRACE(where);
  const std::string kind = e.at("kind").get<std::string>();
  ASSERT_EQ(kindName(node.kind), kind) << describeNode(node);
  if (kind == "dict") {
    const std::vector<std::string> keys = e.at("keys").get<std::vector<std::string>>();
    ASSERT_EQ(node.keys, keys);
    ASSERT_EQ(node.children.size(), keys.size());
    for (size_t i = 0; i < keys.size(); ++i)
      expectTree(node.children[i], e.at("children")[i], where + "['" + keys[i] + "']");
  } else if (kind == "list") {
    ASSERT_EQ(node.children.size(), e.at("children").size());
    for (size_t i = 0; i < node.children.size(); ++i)
      expectTree(node.children[i], e.at("children")[i], where + "[" + std::to_string(i) + "]");
  } else if (kind == "array") {
    EXPECT_EQ(shapeString(node.array.shape),
              shapeString(e.at("shape").get<std::vector<int64_t>>()));
    EXPECT_EQ(node.array.dtype, e.at("dtype").get<std::string>());
    if (e.contains("strings")) {
      EXPECT_EQ(node.array.strings, e.at("strings").get<std::vector<std::string>>());
      EXPECT_TRUE(node.array.data.empty());
      return;
    }
    const std::vector<double> values = e.at("values").get<std::vector<double>>();
    ASSERT_EQ(node.array.data.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i)
      ASSERT_EQ(node.array.data[i], values[i]) << "element " << i;
    EXPECT_TRUE(node.array.strings.empty());
  }
}

}  // namespace smpl::test
