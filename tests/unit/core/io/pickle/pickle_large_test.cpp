// Large array payloads (>= 4 KiB) are read in place by the unpickler
// (PyObj::view) rather than copied: every protocol's large-payload opcodes,
// sizes on both sides of the threshold, C and Fortran order, against numpy's
// own arrays (tests/fixtures/make_large_payloads.py).
#include <gtest/gtest.h>

#include "core/io/mapped_file.h"
#include "core/io/npz.h"
#include "core/io/pickle/pickle.h"

namespace smpl {
namespace {

const std::string kDir = std::string(SMPL_FIXTURE_DIR) + "/large_payloads/";

TEST(PickleLargePayloads, EveryProtocolMatchesNumpy) {
  Result<ArrayDict> expected = readNpzFile(kDir + "expected.npz");
  ASSERT_TRUE(expected.ok()) << expected.message();
  ASSERT_EQ(expected->size(), 8u);
  for (const char* name : {"py2_p2.pkl", "py3_p2.pkl", "py3_p3.pkl", "py3_p4.pkl", "py3_p5.pkl"}) {
    Result<MappedFile> file = MappedFile::open(kDir + name);
    ASSERT_TRUE(file.ok()) << file.message();
    Result<ArrayDict> got = parsePickle(file->data(), file->size(), name);
    ASSERT_TRUE(got.ok()) << name << ": " << got.message();
    for (const auto& [key, want] : *expected) {
      auto it = got->find(key);
      ASSERT_NE(it, got->end()) << name << ": no '" << key << "'";
      EXPECT_EQ(it->second.shape, want.shape) << name << "/" << key;
      EXPECT_EQ(it->second.data, want.data)
          << name << "/" << key;  // exact: same bytes, same widening
    }
  }
}

// A large payload cut short is refused like a small one: the view never
// reaches past the pickle's bytes.
TEST(PickleLargePayloads, TruncatedLargePayloadIsAnError) {
  Result<MappedFile> file = MappedFile::open(kDir + "py3_p3.pkl");
  ASSERT_TRUE(file.ok()) << file.message();
  for (size_t keep : {file->size() / 2, file->size() - 1}) {
    std::vector<uint8_t> cut(file->data(), file->data() + keep);
    Result<ArrayDict> got = parsePickle(cut.data(), cut.size(), "cut.pkl");
    EXPECT_FALSE(got.ok()) << "accepted " << keep << " bytes";
  }
}

}  // namespace
}  // namespace smpl
