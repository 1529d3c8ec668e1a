// JSON -> DataNode (core/io/tree/json_tree.h). The fixtures (EasyMocap's
// list of persons, every conversion rule) are compared with Python's json in
// data_tree_test; here: depth, syntax errors, the memory charge, text.
#include "core/io/tree/json_tree.h"

#include <gtest/gtest.h>

#include <string>

namespace smpl {
namespace {

Result<DataNode> json(const std::string& text) {
  return parseJsonTree(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "f.json");
}

TEST(JsonTree, DepthIsCheckedBeforeParsing) {
  const std::string ok = std::string(32, '[') + "1" + std::string(32, ']');
  Result<DataNode> fine = json(ok);
  ASSERT_TRUE(fine.ok()) << fine.message();
  EXPECT_EQ(fine->array.shape.size(), 32u);  // a 1x1x...x1 array of numbers
  const std::string deep = std::string(33, '[') + "1" + std::string(33, ']');
  Result<DataNode> refused = json(deep);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.message(), "f.json: JSON nested deeper than 32 levels");
  // Brackets inside strings do not count; a million open brackets are refused at once.
  EXPECT_TRUE(json("{\"a\": \"[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[\\\"[[[[\"}").ok());
  EXPECT_FALSE(json(std::string(1000000, '[')).ok());
}

TEST(JsonTree, SyntaxErrorsNameTheByte) {
  Result<DataNode> bad = json("{\"a\": [1, 2,]}");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(), "f.json: not valid JSON (syntax error at byte 13)");
  Result<DataNode> cut = json("{\"a\": [1, 2");
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.message(), "f.json: not valid JSON (truncated)");
  EXPECT_FALSE(json("").ok());
  EXPECT_FALSE(json("{\"a\": NaN}").ok());  // JSON has no NaN
  // Found by json_tree_fuzz: nlohmann throws out_of_range, not parse_error, for these.
  Result<DataNode> huge = json("[-0.25093E92499923706]");
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.message(), "f.json: not valid JSON (a number out of range)");
}

TEST(JsonTree, TextAndNumbers) {
  Result<DataNode> t = json("{\"s\": \"a\\u00e9\\\"\", \"n\": [1e2, -0, 3], \"b\": [true]}");
  ASSERT_TRUE(t.ok()) << t.message();
  ASSERT_NE(t->leaf("s"), nullptr);
  EXPECT_EQ(t->leaf("s")->strings, std::vector<std::string>{"a\xc3\xa9\""});
  EXPECT_EQ(t->leaf("s")->dtype, "<U3");
  EXPECT_EQ(t->leaf("n")->data, (std::vector<double>{100, 0, 3}));
  EXPECT_EQ(t->leaf("n")->dtype, "<f8");
  EXPECT_EQ(t->leaf("b")->dtype, "|b1");
}

TEST(JsonTree, TwelveBytesPerByteAreChargedBeforeParsing) {
  std::string big = "[";
  for (int i = 0; i < 200000; ++i) big += "0,";
  big += "0]";  // 400 KB of text: 4.8 MB charged
  setMemoryLimit(4ull << 20);
  Result<DataNode> refused = json(big);
  setMemoryLimit(0);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.message().rfind("f.json: parsing the JSON would need 4.6 MiB", 0), 0u)
      << refused.message();
  Result<DataNode> fine = json(big);
  ASSERT_TRUE(fine.ok()) << fine.message();
  EXPECT_EQ(fine->array.data.size(), 200001u);
  EXPECT_GE(fine->array.charge.bytes(), 200001u * sizeof(double));
}

}  // namespace
}  // namespace smpl
