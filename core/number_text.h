// The one grammar for numbers typed on the command line (every numeric option
// of smpl-export, cli/options.cpp, and --memory-limit's size), so that "0x10"
// or " 5" is not 16 or 5 for one option and refused by another (strtod reads
// hexadecimal, "inf", "nan" and leading blanks; strtol reads octal and hex).
//
// Grammar (docs/cli.md "Numbers"), the whole text and nothing else:
//   integer  -?[0-9]+                           ("12", "-3"; not "+3", "1e3", "4.0", "0x10")
//   decimal  -?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?
//                                               ("0.5", ".5", "5.", "-1.2e-3"; not "inf", " 1")
// No sign '+', no blanks, no hexadecimal, no "inf"/"nan", no digit separators;
// decimal values must be finite (1e999 is refused) and both kinds must lie in
// the range the caller gives.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/result.h"

namespace smpl {

// Length of the longest prefix of `text` that is a decimal number (0: none);
// for values followed by a unit ("512M": 3).
size_t decimalPrefixLength(std::string_view text);

// `text` as a decimal number in [lo, hi]. Errors (one line, to be prefixed
// with the option): "'0x10' is not a decimal number", "'5000' is not in
// [1, 1000]".
Result<double> parseDecimal(std::string_view text, double lo, double hi);

// `text` as an integer in [lo, hi]; errors as parseDecimal ("'1e3' is not an
// integer").
Result<int64_t> parseInteger(std::string_view text, int64_t lo, int64_t hi);

}  // namespace smpl
