// readBetasFile (core/models/betas_file.h): .json arrays and {"betas": [...]},
// errors naming the file (non-numbers, invalid JSON, missing key), and the
// range check where the betas enter.
#include "core/models/betas_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace smpl {
namespace {

TEST(BetasFile, Json) {
  const std::string path = testing::TempDir() + "betas.json";
  std::ofstream(path) << "{\"betas\": [0.5, -1]}";
  Result<std::vector<double>> b = readBetasFile(path);
  ASSERT_TRUE(b.ok()) << b.message();
  EXPECT_EQ(*b, (std::vector<double>{0.5, -1}));
  std::ofstream(path) << "[0.25]";
  ASSERT_TRUE(readBetasFile(path).ok());
  EXPECT_EQ(*readBetasFile(path), (std::vector<double>{0.25}));
  std::ofstream(path) << "[1, \"x\"]";
  Result<std::vector<double>> bad = readBetasFile(path);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(), path + ": 'betas' holds a non-number");
  std::ofstream(path) << "[1, 2";
  Result<std::vector<double>> truncated = readBetasFile(path);
  ASSERT_FALSE(truncated.ok());
  EXPECT_EQ(truncated.message(), path + ": not valid JSON");
  std::ofstream(path) << "[1, 5000]";
  Result<std::vector<double>> big = readBetasFile(path);
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.message().rfind(path + ": 'betas'[1] is 5000", 0), 0u) << big.message();
}

TEST(BetasFile, NumpyNeedsItsKey) {
  Result<std::vector<double>> none =
      readBetasFile(std::string(SMPL_FIXTURE_DIR) + "/motions/smpl_72.npz");  // no 'betas' member
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.message().find("missing key 'betas'"), std::string::npos) << none.message();
  Result<std::vector<double>> missing = readBetasFile(testing::TempDir() + "no_such_betas.npy");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("no_such_betas.npy"), std::string::npos);
}

}  // namespace
}  // namespace smpl
