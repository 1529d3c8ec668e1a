// Tests for the .npy reader. Good inputs are written by numpy
// (tests/fixtures/make_npy_cases.py) and compared with the values numpy
// itself reports; bad inputs are built here by editing headers and bytes.
#include "core/io/npy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::readAll;

const std::string kCases = std::string(SMPL_FIXTURE_DIR) + "/npy_cases/";

Result<Array> parse(const std::string& bytes, const std::string& ctx = "beta.npy") {
  return parseNpy(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), ctx);
}

// A v1 .npy image with the given header dict text, padded as numpy pads it.
std::string makeNpy(const std::string& dict, const std::string& payload, int version = 1) {
  const size_t prefix = version == 1 ? 10 : 12;
  std::string header = dict;
  while ((prefix + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out = std::string("\x93NUMPY", 6) + static_cast<char>(version) + '\0';
  const size_t len = header.size();
  for (size_t i = 0; i < prefix - 8; ++i) out += static_cast<char>((len >> (8 * i)) & 0xff);
  return out + header + payload;
}

std::string doubles(std::vector<double> v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * 8);
}

void expectValue(double got, const nlohmann::json& want, size_t i) {
  if (want.is_string()) {
    const std::string w = want.get<std::string>();
    if (w == "nan")
      EXPECT_TRUE(std::isnan(got)) << "element " << i;
    else
      EXPECT_EQ(got, w == "inf" ? INFINITY : -INFINITY) << "element " << i;
    return;
  }
  const double w = want.get<double>();
  EXPECT_EQ(got, w) << "element " << i;
  EXPECT_EQ(std::signbit(got), std::signbit(w)) << "sign of element " << i;
}

void expectArray(const Array& a, const nlohmann::json& e) {
  EXPECT_EQ(shapeString(a.shape), shapeString(e.at("shape").get<std::vector<int64_t>>()));
  EXPECT_EQ(a.dtype, e.at("dtype").get<std::string>());
  if (e.contains("strings")) {
    EXPECT_TRUE(a.isString());
    EXPECT_TRUE(a.data.empty());
    EXPECT_EQ(a.strings, e.at("strings").get<std::vector<std::string>>());
    return;
  }
  EXPECT_FALSE(a.isString());
  const nlohmann::json& values = e.at("values");
  ASSERT_EQ(a.data.size(), values.size());
  for (size_t i = 0; i < values.size(); ++i) expectValue(a.data[i], values[i], i);
}

TEST(Npy, EveryNumpyCaseMatchesNumpy) {
  nlohmann::json expected = nlohmann::json::parse(readAll(kCases + "expected.json"));
  ASSERT_GE(expected.size(), 40u);
  for (auto it = expected.begin(); it != expected.end(); ++it) {
    SCOPED_TRACE(it.key());
    Result<Array> a = readNpyFile(kCases + it.key());
    ASSERT_TRUE(a.ok()) << a.message();
    expectArray(*a, it.value());
  }
}

TEST(Npy, AmassGenderIsAZeroDimensionalString) {
  Result<Array> a = readNpyFile(kCases + "gender.npy");
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_TRUE(a->shape.empty());
  EXPECT_EQ(a->size(), 1);
  ASSERT_EQ(a->strings.size(), 1u);
  EXPECT_EQ(a->strings[0], "female");
}

TEST(Npy, MissingFileNamesThePath) {
  Result<Array> a = readNpyFile(kCases + "does_not_exist.npy");
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.message().find("does_not_exist.npy: cannot open"), std::string::npos) << a.message();
}

TEST(Npy, EveryTruncationIsAnErrorNamingTheFile) {
  for (const char* name :
       {"f8_fortran_2d.npy", "names_u.npy", "scalar_f8.npy", "version_2.npy", "bytes_s.npy"}) {
    const std::string full = readAll(kCases + name);
    ASSERT_TRUE(parse(full).ok()) << name;
    const size_t data_start = full.find('\n') + 1;
    for (size_t len = 0; len < full.size(); ++len) {
      Result<Array> a = parse(full.substr(0, len), "cut.npy");
      ASSERT_FALSE(a.ok()) << name << " cut at " << len;
      EXPECT_EQ(a.message().rfind("cut.npy: ", 0), 0u) << a.message();
      if (len < data_start) continue;
      const std::string want = "truncated data: expected " +
                               std::to_string(full.size() - data_start) + " bytes, found " +
                               std::to_string(len - data_start);
      EXPECT_NE(a.message().find(want), std::string::npos) << a.message();
    }
  }
}

TEST(Npy, HandBuiltHeaderParses) {
  Result<Array> a = parse(
      makeNpy("{'shape': (3L,), 'fortran_order': False, 'descr': '<f8'}", doubles({1, 2, 3})));
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_EQ(a->data, (std::vector<double>{1, 2, 3}));
  Result<Array> v2 = parse(makeNpy(
      "{\"descr\": \"<f8\", \"fortran_order\": True, \"shape\": (1, 2), }", doubles({4, 5}), 2));
  ASSERT_TRUE(v2.ok()) << v2.message();
  EXPECT_EQ(v2->data, (std::vector<double>{4, 5}));
}

TEST(Npy, TrailingBytesAfterTheDataAreTolerated) {
  Result<Array> a = parse(
      makeNpy("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", doubles({1, 2, 3})));
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_EQ(a->data, (std::vector<double>{1, 2}));
}

struct BadCase {
  std::string bytes;
  std::string keyword;
};

void expectError(const BadCase& c) {
  Result<Array> a = parse(c.bytes, "bad.npy");
  ASSERT_FALSE(a.ok()) << "accepted; expected '" << c.keyword << "'";
  EXPECT_EQ(a.message().rfind("bad.npy: ", 0), 0u) << a.message();
  EXPECT_NE(a.message().find(c.keyword), std::string::npos) << a.message();
}

std::string withDict(const std::string& dict) { return makeNpy(dict, doubles({1, 2, 3})); }

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

TEST(Npy, BadPreambleIsRefused) {
  const std::string good = withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }");
  std::string magic = good, version = good, absurd = good, shortlen = good;
  magic[1] = 'X';
  version[6] = 4;
  absurd[6] = 2;  // v2 reads a 4-byte length: bytes 8..11 now say ~4 GB
  absurd[10] = '\xff';
  absurd[11] = '\x7f';
  shortlen[8] = '\xff';
  shortlen[9] = '\x7f';
  for (const BadCase& c :
       {BadCase{magic, "bad magic"}, BadCase{version, "unsupported .npy version 4.0"},
        BadCase{absurd, "absurd"}, BadCase{shortlen, "truncated .npy header"},
        BadCase{"", "bad magic"}, BadCase{"\x93NUMPY\x01", "bad magic"}})
    expectError(c);
}

TEST(Npy, BadHeaderDictIsRefused) {
  const std::vector<BadCase> cases = {
      {withDict("{'descr': '<f8', 'fortran_order': False}"), "needs 'descr'"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), 'extra': 1}"),
       "unexpected or repeated key 'extra'"},
      {withDict("{'descr': '<f8', 'descr': '<f8', 'fortran_order': False, 'shape': (3,)}"),
       "repeated key 'descr'"},
      {withDict("{'descr': '<f8', 'fortran_order': 0, 'shape': (3,)}"), "True or False"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (-3,)}"), "negative dimension"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': [3]}"), "must be a tuple"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (3 4)}"), "malformed 'shape'"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999,)}"),
       "dimension too large"},
      {withDict("{'descr: '<f8', 'fortran_order': False, 'shape': (3,)}"), "bad .npy header"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (3,)} x"),
       "trailing characters"},
      {withDict("{'descr': '<f8' 'fortran_order': False, 'shape': (3,)}"), "expected ',' or '}'"},
      {withDict("['descr', '<f8']"), "expected a dict"},
      {withDict("{'descr': '<f\\x38', 'fortran_order': False, 'shape': (3,)}"), "escapes"},
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (" + repeat("1,", 65) + ")}"),
       "more than 64 dimensions"},
  };
  for (const BadCase& c : cases) expectError(c);
}

TEST(Npy, UnsupportedDtypesAreRefusedClearly) {
  auto dict = [](const std::string& descr) {
    return withDict("{'descr': " + descr + ", 'fortran_order': False, 'shape': (3,), }");
  };
  const std::vector<BadCase> cases = {
      {dict("'|O'"), "object arrays ('|O') are not supported"},
      {dict("[('x', '<f4'), ('y', '<f4')]"), "structured dtypes"},
      {dict("'|V8'"), "structured/void dtype"},
      {dict("'<c16'"), "unsupported dtype '<c16'"},
      {dict("'<f16'"), "unsupported dtype '<f16'"},
      {dict("'<i3'"), "unsupported dtype '<i3'"},
      {dict("'<M8[ns]'"), "unsupported dtype '<M8[ns]'"},
      {dict("'|f8'"), "needs a byte order"},
      {dict("'<U0'"), "unsupported dtype '<U0'"},
      {dict("'f8'"), "unsupported dtype 'f8'"},
      {dict("'<b2'"), "unsupported dtype '<b2'"},
  };
  for (const BadCase& c : cases) expectError(c);
}

TEST(Npy, ShapeAndSizeMismatchReportsBytes) {
  expectError({withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (4,), }"),
               "truncated data: expected 32 bytes, found 24"});
  expectError({withDict("{'descr': '<U2', 'fortran_order': False, 'shape': (4,), }"),
               "truncated data: expected 32 bytes, found 24"});
}

TEST(Npy, HugeDeclaredShapesFailWithoutAllocating) {
  // Each would need terabytes if the reader trusted the header.
  expectError({withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (1000000000000,), }"),
               "truncated data: expected 8000000000000 bytes, found 24"});
  expectError(
      {withDict("{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296), }"),
       "too large"});
  expectError(
      {withDict("{'descr': '|u1', 'fortran_order': False, 'shape': (4611686018427387904, 4, 0), }"),
       "too large"});
  expectError(
      {withDict(
           "{'descr': '<U67108864', 'fortran_order': False, 'shape': (4294967296, 4294967296), }"),
       "too large"});
}

TEST(Npy, InvalidUnicodeIsRefused) {
  const std::string bad("\x00\x00\x11\x00", 4);  // U+110000, beyond Unicode
  expectError({makeNpy("{'descr': '<U1', 'fortran_order': False, 'shape': (1,), }", bad),
               "invalid unicode code point"});
  const std::string surrogate("\x00\xd8\x00\x00", 4);
  expectError({makeNpy("{'descr': '<U1', 'fortran_order': False, 'shape': (1,), }", surrogate),
               "invalid unicode"});
}

TEST(Npy, HalfFloatsDecodeExactly) {
  // Bit patterns from IEEE 754 binary16: smallest subnormal, largest normal, one.
  const std::string bits("\x01\x00\xff\x7b\x00\x3c\x00\xfc", 8);
  Result<Array> a =
      parse(makeNpy("{'descr': '<f2', 'fortran_order': False, 'shape': (4,), }", bits));
  ASSERT_TRUE(a.ok()) << a.message();
  EXPECT_EQ(a->data, (std::vector<double>{std::ldexp(1.0, -24), 65504.0, 1.0, -INFINITY}));
}

}  // namespace
}  // namespace smpl
