// UTF-8 helpers (core/utf8.h): the escaping that makes file-name bytes fit
// for JSON and FBX text.
#include "core/utf8.h"

#include <gtest/gtest.h>

namespace smpl {
namespace {

TEST(Utf8, ValidTextIsKeptInvalidBytesEscaped) {
  EXPECT_EQ(escapeInvalidUtf8("walk_01"), "walk_01");
  EXPECT_EQ(escapeInvalidUtf8("caf\xc3\xa9 \xe2\x9c\x93 \xf0\x9f\x95\xba"),
            "caf\xc3\xa9 \xe2\x9c\x93 \xf0\x9f\x95\xba");  // non-ASCII names stay as they are
  EXPECT_EQ(escapeInvalidUtf8("walk\xff.npz"), "walk\\xff.npz");
  EXPECT_EQ(escapeInvalidUtf8("\xc3"), "\\xc3");                             // truncated
  EXPECT_EQ(escapeInvalidUtf8("\xc0\xaf"), "\\xc0\\xaf");                    // overlong '/'
  EXPECT_EQ(escapeInvalidUtf8("\xed\xa0\x80"), "\\xed\\xa0\\x80");           // surrogate
  EXPECT_EQ(escapeInvalidUtf8("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // > U+10FFFF
  EXPECT_EQ(escapeInvalidUtf8("a\tb"), "a\tb");  // controls are valid UTF-8: JSON escapes them
}

TEST(Utf8, EscapedTextIsValidAndStable) {
  const std::string bytes = "x\xff\xfe\x80y\xe2\x9c";
  const std::string once = escapeInvalidUtf8(bytes);
  EXPECT_TRUE(isValidUtf8(once));
  EXPECT_FALSE(isValidUtf8(bytes));
  EXPECT_EQ(escapeInvalidUtf8(once), once);   // idempotent
  EXPECT_EQ(escapeInvalidUtf8(bytes), once);  // deterministic
}

}  // namespace
}  // namespace smpl
