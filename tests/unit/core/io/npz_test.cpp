// Tests for the .npz reader: archives written by np.savez,
// np.savez_compressed and Python's zipfile (tests/fixtures/make_npy_cases.py)
// against the values np.load returned; errors must name archive and member.
#include "core/io/npz.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
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

Result<ArrayDict> parse(const std::string& bytes) {
  return parseNpz(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), "model.npz");
}

std::string le(uint64_t v, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += static_cast<char>(i < 8 ? (v >> (8 * i)) & 0xff : 0);
  return s;
}

// A stored-only zip; enough to wrap hand-made members.
std::string storedZip(const std::vector<std::pair<std::string, std::string>>& members) {
  std::string body, cd;
  for (const auto& m : members) {
    const uint32_t crc = static_cast<uint32_t>(crc32(
        0, reinterpret_cast<const Bytef*>(m.second.data()), static_cast<uInt>(m.second.size())));
    const std::string common = le(20, 2) + le(0, 6) + le(0x21, 2) + le(crc, 4) +
                               le(m.second.size(), 4) + le(m.second.size(), 4) +
                               le(m.first.size(), 2) + le(0, 2);
    cd += le(0x02014b50, 4) + le(20, 2) + common + le(0, 10) + le(body.size(), 4) + m.first;
    body += le(0x04034b50, 4) + common + m.first + m.second;
  }
  return body + cd + le(0x06054b50, 4) + le(0, 4) + le(members.size(), 2) + le(members.size(), 2) +
         le(cd.size(), 4) + le(body.size(), 4) + le(0, 2);
}

std::string npy(const std::string& dict, const std::string& payload) {
  std::string header = dict;
  while ((10 + header.size() + 1) % 64) header += ' ';
  header += '\n';
  return std::string("\x93NUMPY\x01\x00", 8) + le(header.size(), 2) + header + payload;
}

void expectArray(const Array& a, const nlohmann::json& e) {
  EXPECT_EQ(shapeString(a.shape), shapeString(e.at("shape").get<std::vector<int64_t>>()));
  EXPECT_EQ(a.dtype, e.at("dtype").get<std::string>());
  if (e.contains("strings")) {
    EXPECT_EQ(a.strings, e.at("strings").get<std::vector<std::string>>());
    return;
  }
  const nlohmann::json& values = e.at("values");
  ASSERT_EQ(a.data.size(), values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    ASSERT_FALSE(values[i].is_string()) << "fixture archives hold finite values only";
    EXPECT_EQ(a.data[i], values[i].get<double>()) << "element " << i;
  }
}

TEST(Npz, ArchivesMatchNpLoad) {
  nlohmann::json expected = nlohmann::json::parse(readAll(kCases + "expected_npz.json"));
  ASSERT_EQ(expected.size(), 4u);
  for (auto file = expected.begin(); file != expected.end(); ++file) {
    SCOPED_TRACE(file.key());
    Result<ArrayDict> d = readNpzFile(kCases + file.key());
    ASSERT_TRUE(d.ok()) << d.message();
    ASSERT_EQ(d->size(), file.value().size());
    for (auto key = file.value().begin(); key != file.value().end(); ++key) {
      SCOPED_TRACE(key.key());
      auto it = d->find(key.key());
      ASSERT_NE(it, d->end());
      expectArray(it->second, key.value());
    }
  }
}

TEST(Npz, ZipErrorsNameTheFileNotItsDirectory) {
  Result<ArrayDict> d = readNpzFile(kCases + "names_u.npy");  // an .npy is not a zip
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.message().rfind("names_u.npy: not a zip archive", 0), 0u) << d.message();
  Result<ArrayDict> missing = readNpzFile(kCases + "missing.npz");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("missing.npz: cannot open"), std::string::npos)
      << missing.message();
}

TEST(Npz, MemberErrorsNameArchiveAndMember) {
  const std::string good =
      npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", std::string(16, '\0'));
  const std::string cut =
      npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", std::string(10, '\0'));
  Result<ArrayDict> d = parse(storedZip({{"betas.npy", good}, {"shapedirs.npy", cut}}));
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.message(), "model.npz/shapedirs.npy: truncated data: expected 16 bytes, found 10");
  const std::string obj =
      npy("{'descr': '|O', 'fortran_order': False, 'shape': (2,), }", std::string(16, '\0'));
  // Eager reads skip object members (not numeric data); asking for one by name is an error naming
  // it.
  Result<ArrayDict> o = parse(storedZip({{"kintree_table.npy", obj}, {"betas.npy", good}}));
  ASSERT_TRUE(o.ok()) << o.message();
  EXPECT_EQ(o->count("kintree_table"), 0u);
  EXPECT_EQ(o->count("betas"), 1u);
  const std::string zip = storedZip({{"kintree_table.npy", obj}});
  Result<NpzArchive> npz =
      NpzArchive::fromBytes(reinterpret_cast<const uint8_t*>(zip.data()), zip.size(), "model.npz");
  ASSERT_TRUE(npz.ok()) << npz.message();
  Result<Array> g = npz->get("kintree_table");
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.message(),
            "model.npz: 'kintree_table' is an object array ('|O'); expected numbers or text");
  Result<ArrayDict> txt = parse(storedZip({{"readme.txt", "hello"}}));
  ASSERT_FALSE(txt.ok());
  EXPECT_EQ(txt.message().rfind("model.npz/readme.txt: not an .npy file", 0), 0u) << txt.message();
}

TEST(Npz, KeysDropTheNpySuffixAndDuplicatesAreRefused) {
  const std::string a =
      npy("{'descr': '<i2', 'fortran_order': False, 'shape': (), }", std::string("\x07\x00", 2));
  Result<ArrayDict> d = parse(storedZip({{"dir/", ""}, {"fps.npy", a}, {"fps.npy.npy", a}}));
  ASSERT_TRUE(d.ok()) << d.message();
  ASSERT_EQ(d->size(), 2u);
  EXPECT_EQ(d->at("fps").data, std::vector<double>{7});
  EXPECT_EQ(d->count("fps.npy"), 1u);
  Result<ArrayDict> dup = parse(storedZip({{"fps.npy", a}, {"fps", a}}));
  ASSERT_FALSE(dup.ok());
  EXPECT_EQ(dup.message(), "model.npz/fps: duplicate member 'fps'");
}

TEST(Npz, EveryTruncationOfAStoredArchiveIsAnError) {
  const std::string full = readAll(kCases + "stored.npz");
  for (size_t len = 0; len < full.size(); ++len) {
    Result<ArrayDict> d = parse(full.substr(0, len));
    ASSERT_FALSE(d.ok()) << "cut at " << len;
    EXPECT_EQ(d.message().rfind("model.npz", 0), 0u) << d.message();
  }
}

// Lazy: members nobody asks for are never inflated or parsed, so a corrupt,
// oddly compressed or huge unused member cannot make a read fail.
TEST(Npz, UnusedMembersAreNeverDecoded) {
  const std::string good =
      npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", std::string(16, '\0'));
  std::string zip = storedZip(
      {{"betas.npy", good},
       {"junk.npy", "this is not an npy file at all"},
       {"huge.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }", "")}});
  Result<NpzArchive> npz =
      NpzArchive::fromBytes(reinterpret_cast<const uint8_t*>(zip.data()), zip.size(), "m.npz");
  ASSERT_TRUE(npz.ok()) << npz.message();
  EXPECT_EQ(npz->keys(), (std::vector<std::string>{"betas", "junk", "huge"}));
  Result<ArrayDict> d = npz->read({"betas", "absent"});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->size(), 1u);
  EXPECT_EQ(d->at("betas").shape, std::vector<int64_t>{2});
  EXPECT_FALSE(npz->get("junk").ok());
  EXPECT_FALSE(parse(zip).ok());  // the eager reader does parse them
  // An unsupported compression method on an unused member: listing still works.
  std::string odd = storedZip({{"betas.npy", good}, {"odd.npy", good}});
  const size_t second_cd =
      odd.find(std::string("PK\x01\x02", 4), odd.find(std::string("PK\x01\x02", 4)) + 1);
  odd[second_cd + 10] = 99;  // central directory: compression method
  Result<NpzArchive> lazy =
      NpzArchive::fromBytes(reinterpret_cast<const uint8_t*>(odd.data()), odd.size(), "m.npz");
  ASSERT_TRUE(lazy.ok()) << lazy.message();
  EXPECT_TRUE(lazy->read({"betas"}).ok());
  Result<Array> bad = lazy->get("odd");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("unsupported compression method 99"), std::string::npos)
      << bad.message();
}

// Found by npz_fuzz: an empty stored member made the header probe call
// memcpy(nullptr, ..., 0) (undefined behaviour; UBSan aborts the test build).
TEST(Npz, EmptyStoredMemberIsAnErrorNotUndefinedBehaviour) {
  Result<ArrayDict> d = parse(storedZip({{"betas.npy", ""}}));
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.message().rfind("model.npz/betas.npy: ", 0), 0u) << d.message();
}

}  // namespace
}  // namespace smpl
