// runExport: the final finite check stops a NaN before any writer (exit 3,
// nothing written), and the sidecar records a producer hash that depends on
// the options that change the output and not on those that do not.
#include "cli/export_job.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"
#include "core/io/file_io.h"
#include "exporter/metadata_json.h"

namespace smpl {
namespace {

class ExportJobTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "export_job_test_" + std::to_string(::getpid());
    ::mkdir(dir_.c_str(), 0755);
    out_ = dir_ + "/body.glb";
  }
  void TearDown() override {
    std::remove(out_.c_str());
    std::remove((out_ + ".smpl.json").c_str());
    ::rmdir(dir_.c_str());
  }
  Settings settings(std::vector<const char*> extra) const {
    std::vector<const char*> argv = {"smpl-export", "--model",    "builtin",
                                     "--out",       out_.c_str(), "-q"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    Result<Settings> s = parseSettings(static_cast<int>(argv.size()), argv.data());
    EXPECT_TRUE(s.ok()) << s.message();
    return *s;
  }
  std::string producer() const {
    Result<std::vector<uint8_t>> text = readFileBytes(out_ + ".smpl.json");
    return text ? producerHashOf(std::string(text->begin(), text->end())) : "";
  }
  std::string dir_, out_;
};

// A NaN the loaders never saw (a model built in code) reaches the asset as a
// morph delta; runExport must refuse before writing.
TEST_F(ExportJobTest, NonFiniteAssetIsNotWritten) {
  BodyModel model = demoBody();
  model.posedirs(3 * 7 + 1, 0) = std::numeric_limits<double>::quiet_NaN();
  Result<ExportReport> r = runExport(model, settings({}), ExportJob{out_, {}, false, ""});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(exitCodeFor(r.kind()), kExitExport);
  EXPECT_EQ(r.message().rfind("Error exporting " + out_ + ": morph target ", 0), 0u) << r.message();
  EXPECT_NE(r.message().find("vertex 7 is not finite (nan)"), std::string::npos) << r.message();
  struct stat st;
  EXPECT_NE(::stat(out_.c_str(), &st), 0);
  EXPECT_NE(::stat((out_ + ".smpl.json").c_str(), &st), 0);
}

TEST_F(ExportJobTest, SidecarRecordsWhatProducedTheOutput) {
  const BodyModel model = demoBody();
  auto hashWith = [&](std::vector<const char*> extra) {
    Result<ExportReport> r = runExport(model, settings(extra), ExportJob{out_, {}, false, ""});
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.message());
    return producer();
  };
  const std::string plain = hashWith({});
  EXPECT_EQ(plain.size(), 16u);
  EXPECT_EQ(hashWith({}), plain);                         // deterministic
  EXPECT_NE(hashWith({"--max-influences", "2"}), plain);  // changes the bytes
  EXPECT_NE(hashWith({"--betas", "0.5"}), plain);
  EXPECT_EQ(hashWith({"--memory-limit", "1G"}), plain);  // does not
}

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
