// The one number grammar of the command line (core/number_text.h).
#include "core/number_text.h"

#include <gtest/gtest.h>

#include <cfloat>

namespace smpl {
namespace {

TEST(NumberText, DecimalAcceptsPlainDecimalsOnly) {
  for (const char* ok : {"0", "12", "-3", "0.5", ".5", "5.", "-1.2e-3", "1e3", "2E+2", "007"})
    EXPECT_TRUE(parseDecimal(ok, -DBL_MAX, DBL_MAX).ok()) << ok;
  EXPECT_DOUBLE_EQ(*parseDecimal("-1.25e2", -DBL_MAX, DBL_MAX), -125.0);
  EXPECT_DOUBLE_EQ(*parseDecimal(".5", -DBL_MAX, DBL_MAX), 0.5);
  for (const char* bad : {"", "0x10", "0X1p4", "+5", " 5", "5 ", "1,5", "inf", "-inf", "nan", "1e",
                          "e5", ".", "-", "--1", "1.2.3", "1_000", "\xef\xbc\x95", "5\n"}) {
    Result<double> r = parseDecimal(bad, -DBL_MAX, DBL_MAX);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.message().find("is not a decimal number"), std::string::npos) << r.message();
  }
  EXPECT_NE(parseDecimal("1e999", -DBL_MAX, DBL_MAX).message().find("is not finite"),
            std::string::npos);
}

TEST(NumberText, RangesAreTheCallers) {
  EXPECT_TRUE(parseDecimal("1000", 1, 1000).ok());
  Result<double> r = parseDecimal("1000.5", 1, 1000);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), "'1000.5' is not in [1, 1000]");
  Result<int64_t> i = parseInteger("13", 0, 12);
  ASSERT_FALSE(i.ok());
  EXPECT_EQ(i.message(), "'13' is not in [0, 12]");
  EXPECT_EQ(*parseInteger("-7", -10, 10), -7);
  EXPECT_FALSE(parseInteger("99999999999999999999", INT64_MIN, INT64_MAX).ok());
}

TEST(NumberText, IntegersAreDigitsOnly) {
  for (const char* bad : {"1e3", "4.0", "0x10", "010.", "+3", " 3", "3 ", "", "-", "1_0", "٣"}) {
    Result<int64_t> r = parseInteger(bad, -1000000, 1000000);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.message().find("is not an integer"), std::string::npos) << r.message();
  }
  EXPECT_EQ(*parseInteger("010", 0, 100), 10);  // decimal, never octal
}

TEST(NumberText, DecimalPrefixForUnits) {
  EXPECT_EQ(decimalPrefixLength("512M"), 3u);
  EXPECT_EQ(decimalPrefixLength("1.5GiB"), 3u);
  EXPECT_EQ(decimalPrefixLength("1e3M"), 3u);
  EXPECT_EQ(decimalPrefixLength("1eM"), 1u);  // "e" without digits is the unit's business
  EXPECT_EQ(decimalPrefixLength("0x10M"), 1u);
  EXPECT_EQ(decimalPrefixLength("M"), 0u);
}

}  // namespace
}  // namespace smpl
