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

}  // namespace
}  // namespace smpl
