// Track ids from motion files become file-name components only through
// safeNameComponent(): never a separator, ".", "..", a control byte or an
// empty name; bounded; distinct ids stay distinct and readable ids readable.
#include "core/io/name_component.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace smpl {
namespace {

// What every component must be: one plain name on Linux, Windows and macOS.
void expectPlainComponent(const std::string& c) {
  ASSERT_FALSE(c.empty());
  EXPECT_LE(c.size(), kMaxNameComponent) << c;
  EXPECT_NE(c, ".");
  EXPECT_NE(c, "..");
  EXPECT_NE(c.front(), '.') << c;
  EXPECT_NE(c.back(), '.') << c;
  for (unsigned char ch : c) {
    EXPECT_TRUE(ch > 0x20 && ch < 0x7f) << "byte " << int(ch) << " in " << c;
    EXPECT_EQ(std::string("/\\:*?\"<>|").find(static_cast<char>(ch)), std::string::npos) << c;
  }
}

TEST(NameComponent, ReadableIdsStayAsTheyAre) {
  EXPECT_EQ(safeNameComponent("0"), "0");
  EXPECT_EQ(safeNameComponent("12"), "12");
  EXPECT_EQ(safeNameComponent("-3"), "-3");
  EXPECT_EQ(safeNameComponent("person_2-b"), "person_2-b");
  EXPECT_EQ(safeNameComponent("v1.2"), "v1.2");
}

TEST(NameComponent, PathsAndControlBytesAreEscaped) {
  EXPECT_EQ(safeNameComponent("a/b"), "a%2Fb");
  EXPECT_EQ(safeNameComponent("X/../../../../tmp/victim"), "X%2F..%2F..%2F..%2F..%2Ftmp%2Fvictim");
  EXPECT_EQ(safeNameComponent("a\\b"), "a%5Cb");
  EXPECT_EQ(safeNameComponent("."), "%2E");
  EXPECT_EQ(safeNameComponent(".."), "%2E%2E");
  EXPECT_EQ(safeNameComponent(".hidden"), "%2Ehidden");
  EXPECT_EQ(safeNameComponent("end."), "end%2E");
  EXPECT_EQ(safeNameComponent("x\n\x1b[2J"), "x%0A%1B%5B2J");
  EXPECT_EQ(safeNameComponent("50%"), "50%25");
  EXPECT_EQ(safeNameComponent("a b"), "a%20b");
  EXPECT_EQ(safeNameComponent(std::string("a\0b", 3)), "a%00b");
  EXPECT_EQ(safeNameComponent("Jos\xc3\xa9"), "Jos%C3%A9");
  EXPECT_EQ(safeNameComponent(""), "%");
  for (const char* id : {"a/b", ".", "..", "", "x\n", "C:", "con?", "~", "a~b"})
    expectPlainComponent(safeNameComponent(id));
}

TEST(NameComponent, LongIdsAreBoundedAndStayDistinct) {
  const std::string digits300(300, '7');
  std::string other = digits300;
  other.back() = '8';
  const std::string a = safeNameComponent(digits300), b = safeNameComponent(other);
  expectPlainComponent(a);
  expectPlainComponent(b);
  EXPECT_EQ(a.size(), kMaxNameComponent);
  EXPECT_NE(a, b);
  EXPECT_EQ(a.substr(0, 10), "7777777777");
  EXPECT_NE(a.find('~'), std::string::npos);
  EXPECT_FALSE(idOfNameComponent(a).has_value());  // hashed: not reversible
  // Escapes near the cut are never split: every '%' is followed by two hex digits.
  for (size_t pad = 0; pad < 6; ++pad) {
    const std::string id = std::string(pad, 'p') + std::string(40, '/');
    const std::string c = safeNameComponent(id);
    expectPlainComponent(c);
    const std::string head = c.substr(0, c.find('~'));
    for (size_t i = 0; i < head.size(); ++i)
      if (head[i] == '%') {
        ASSERT_LE(i + 2, head.size() - 1) << c;
        i += 2;
      }
  }
  // A bounded name never equals the short name of another id: '~' is escaped there.
  EXPECT_EQ(safeNameComponent("~"), "%7E");
}

TEST(NameComponent, ShortComponentsGiveTheirIdBack) {
  std::set<std::string> seen;
  const std::string ids[] = {"0",           "1",
                             "01",          "a/b",
                             "a%2Fb",       ".",
                             "..",          "",
                             "%",           "x\n",
                             "Jos\xc3\xa9", std::string("\0", 1),
                             "~1",          "9223372036854775807"};
  for (const std::string& id : ids) {
    const std::string c = safeNameComponent(id);
    EXPECT_TRUE(seen.insert(c).second) << "two ids give " << c;
    const std::optional<std::string> back = idOfNameComponent(c);
    ASSERT_TRUE(back.has_value()) << c;
    EXPECT_EQ(*back, id);
  }
  EXPECT_FALSE(idOfNameComponent("%2").has_value());
  EXPECT_FALSE(idOfNameComponent("%2f").has_value());   // lower-case: never made
  EXPECT_FALSE(idOfNameComponent("a%62").has_value());  // "ab" maps to "ab", not "a%62"
}

}  // namespace
}  // namespace smpl
