// errorLine (request/error_line.h): one printable line of at most
// 4 KiB that always keeps its reason.
#include "request/error_line.h"

#include <gtest/gtest.h>

#include <string>

namespace smpl {
namespace {

// Error lines keep their reason: a path over 1 KiB loses its middle wherever
// it appears, the whole line stays within 4 KiB, short lines are unchanged.
TEST(ErrorLine, LongPathsLoseTheirMiddleNotTheReason) {
  EXPECT_EQ(errorLine("saving", "out/x.glb", "out/x.glb: cannot create: Permission denied"),
            "Error saving out/x.glb: cannot create: Permission denied");
  EXPECT_EQ(errorLine("loading", "m.npz", "no 'f'"), "Error loading m.npz: no 'f'");
  const std::string path = "/data/" + std::string(6000, 'a') + "/x.glb";
  const std::string line =
      errorLine("saving", path, path + ": cannot create temporary file: File name too long");
  EXPECT_LE(line.size(), 1100u);  // the path once, shortened to 1 KiB
  EXPECT_EQ(line.rfind("Error saving /data/aaa", 0), 0u) << line;
  EXPECT_NE(line.find("aaa...aaa"), std::string::npos) << line;
  EXPECT_NE(line.find("aaa/x.glb: cannot create temporary file: File name too long"),
            std::string::npos)
      << line;
  // A reason that names the path twice and is long itself: at most 4 KiB.
  const std::string twice =
      errorLine("in", "arguments", path + " and " + path + std::string(5000, 'b') + " clash");
  EXPECT_LE(twice.size(), 4096u);
  EXPECT_TRUE(twice.size() > 6 && twice.substr(twice.size() - 6) == " clash") << twice;
}

}  // namespace
}  // namespace smpl
