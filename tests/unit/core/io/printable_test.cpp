// printable(): untrusted bytes become one printable line; readers use it for
// every name that comes from a file.
#include "core/io/printable.h"

#include <gtest/gtest.h>

#include "core/io/npy.h"
#include "core/io/pickle/pickle.h"

namespace smpl {
namespace {

bool allPrintable(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7f) return false;
  return true;
}

TEST(Printable, EscapesControlsDelAndBadUtf8) {
  EXPECT_EQ(printable("plain name.npy"), "plain name.npy");
  EXPECT_EQ(printable("ke\x1b[2Jy\r\n"), "ke\\x1b[2Jy\\x0d\\x0a");
  EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable("\x7f"), "\\x7f");
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x9c\x93"), "caf\xc3\xa9 \xe2\x9c\x93");  // valid UTF-8 kept
  EXPECT_EQ(printable("\xc2\x9b"
                      "31m"),
            "\\xc2\\x9b31m");                               // C1 CSI
  EXPECT_EQ(printable("\xff\xc3"), "\\xff\\xc3");           // invalid, truncated
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // surrogate
}

TEST(Printable, IsIdempotentAndTruncates) {
  const std::string once = printable("x\x1b\\y\r");
  EXPECT_EQ(printable(once), once);
  const std::string long_text(10000, 'a');
  EXPECT_EQ(printable(long_text, 100), std::string(100, 'a') + "...");
  EXPECT_EQ(printable("\xe2\x9c\x93\xe2\x9c\x93\xe2\x9c\x93", 4),
            "\xe2\x9c\x93\xe2\x9c\x93...");  // whole characters
}

TEST(Printable, NpyHeaderKeyIsEscapedInTheError) {
  std::string dict =
      "{'descr': '<f8', 'fortran_order': False, 'shape': (1,), '\x1b]0;pwned\x07\r': 1}";
  while ((10 + dict.size() + 1) % 64 != 0) dict += ' ';
  dict += '\n';
  const std::string bytes = std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(dict.size()) +
                            '\0' + dict + std::string(8, '\0');
  Result<Array> a = parseNpy(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "b.npy");
  ASSERT_FALSE(a.ok());
  EXPECT_TRUE(allPrintable(a.message())) << a.message();
  EXPECT_NE(a.message().find("\\x1b]0;pwned\\x07\\x0d"), std::string::npos) << a.message();
}

TEST(Printable, PickleGlobalNameIsEscapedInTheError) {
  const std::string p =
      "\x80\x02"
      "cos\x1b[31m\nsys\rtem\n"
      ".";
  Result<ArrayDict> d = parsePickle(reinterpret_cast<const uint8_t*>(p.data()), p.size(), "m.pkl");
  ASSERT_FALSE(d.ok());
  EXPECT_TRUE(allPrintable(d.message())) << d.message();
  EXPECT_NE(d.message().find("os\\x1b[31m.sys\\x0dtem"), std::string::npos) << d.message();
}

// Error lines keep their reason: a long path loses its middle, never the end.
TEST(Printable, MiddleIsCutNotTheEnd) {
  const std::string path = "/data/" + std::string(5000, 'a') + "/out.glb";
  const std::string line = "Error saving " + path + ": cannot create: File name too long";
  const std::string cut = printableMiddle(line, 4096);
  EXPECT_LE(cut.size(), 4096u);
  EXPECT_EQ(cut.rfind("Error saving /data/aaa", 0), 0u);
  EXPECT_NE(cut.find("aaa...aaa"), std::string::npos);
  EXPECT_NE(cut.find("/out.glb: cannot create: File name too long"), std::string::npos);
  EXPECT_EQ(printableMiddle(cut, 4096), cut);  // idempotent
  EXPECT_EQ(printableMiddle("short", 4096), "short");
}

TEST(Printable, MiddleCutKeepsCharactersAndEscapesWhole) {
  // Multi-byte characters and \xNN escapes around the cut are never split.
  std::string text;
  for (int i = 0; i < 200; ++i) text += i % 2 ? "\xe2\x9c\x93" : "\x01";
  for (size_t max : {20u, 21u, 22u, 23u, 24u, 25u, 50u, 51u}) {
    const std::string cut = printableMiddle(text, max);
    EXPECT_LE(cut.size(), max);
    EXPECT_EQ(printable(cut, 100000), cut) << max;  // still well-formed, printable text
    const size_t dots = cut.find("...");
    ASSERT_NE(dots, std::string::npos);
    const std::string head = cut.substr(0, dots), tail = cut.substr(dots + 3);
    const std::string all = printable(text, 100000);
    EXPECT_EQ(all.compare(0, head.size(), head), 0) << max;
    EXPECT_EQ(all.compare(all.size() - tail.size(), tail.size(), tail), 0) << max;
    EXPECT_TRUE(head.empty() || head.back() != '\\');
    EXPECT_TRUE(tail.empty() ||
                (tail[0] == '\\' || (static_cast<uint8_t>(tail[0]) & 0xC0) != 0x80));
  }
}

}  // namespace
}  // namespace smpl
