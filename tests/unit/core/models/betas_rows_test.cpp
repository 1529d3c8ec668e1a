// Per-frame betas (T,B): identical rows -> the row; differing rows -> their
// mean with the largest deviation; never flattened. Expected values are
// numpy's (tests/fixtures/make_released_layouts.py).
#include "core/models/betas_rows.h"

#include <gtest/gtest.h>

#include "core/io/npz.h"
#include "core/models/betas_file.h"
#include "core/motions/motion.h"
#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::numbers;

const std::string kReleased = std::string(SMPL_FIXTURE_DIR) + "/released/";

ArrayDict expected() {
  Result<ArrayDict> e = readNpzFile(kReleased + "betas_rows_expected.npz");
  EXPECT_TRUE(e.ok()) << e.message();
  return e.ok() ? *e : ArrayDict();
}

void expectNear(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "beta " << i;
}

TEST(BetasRows, IdenticalRowsGiveTheRowWithoutNote) {
  Result<Motion> m = loadMotion(kReleased + "betas_rows_same.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  expectNear(m->betas, expected().at("row").data);
  EXPECT_TRUE(m->notes.empty());
}

TEST(BetasRows, DifferingRowsGiveTheMeanAndANote) {
  const ArrayDict e = expected();
  Result<Motion> m = loadMotion(kReleased + "betas_rows_differ.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  expectNear(m->betas, e.at("mean").data);
  ASSERT_EQ(m->notes.size(), 1u);
  char dev[32];
  std::snprintf(dev, sizeof dev, "%.6g", e.at("max_deviation").data[0]);
  EXPECT_NE(m->notes[0].find("30 per-frame rows differ"), std::string::npos) << m->notes[0];
  EXPECT_NE(m->notes[0].find(dev), std::string::npos) << m->notes[0] << " lacks " << dev;
}

TEST(BetasRows, BetasFileFollowsTheSameRule) {
  const ArrayDict e = expected();
  std::string note;
  Result<std::vector<double>> b = readBetasFile(kReleased + "betas_rows_differ.npy", &note);
  ASSERT_TRUE(b.ok()) << b.message();
  expectNear(*b, e.at("mean").data);
  EXPECT_NE(note.find("rows differ"), std::string::npos) << note;
  Result<BetasRows> same = collapseBetasRows(numbers({3, 2}, {1, 2, 1, 2, 1, 2}), "b.npy");
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same->betas, (std::vector<double>{1, 2}));
  EXPECT_FALSE(same->averaged);
  Result<BetasRows> mixed = collapseBetasRows(numbers({2, 2}, {1, 2, 3, 6}), "b.npy");
  ASSERT_TRUE(mixed.ok());
  EXPECT_EQ(mixed->betas, (std::vector<double>{2, 4}));  // flattening would give (1, 2)
  EXPECT_DOUBLE_EQ(mixed->max_deviation, 2.0);
  Result<BetasRows> cube = collapseBetasRows(numbers({1, 1, 2}, {1, 2}), "b.npy");
  ASSERT_FALSE(cube.ok());
  EXPECT_EQ(cube.message(), "b.npy: 'betas' has shape (1,1,2); expected (B,) or (T,B) numbers");
}

}  // namespace
}  // namespace smpl
