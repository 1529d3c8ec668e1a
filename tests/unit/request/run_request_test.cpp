// runExportRequest / runExportJob (request/run_request.h): the final
// finite check stops a NaN before any writer (exit 3, nothing written); the
// sidecar records a producer hash that depends on the options that change
// the output and not on those that do not; each motion is decoded once, and
// a model folder picks from the decoded motion (never reading it again); the
// model's checks run once the model is known; the path guard runs first.
#include "request/run_request.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "cli/settings.h"
#include "core/demo/demo_body.h"
#include "core/io/file_io.h"
#include "core/models/model_loader.h"
#include "exporter/metadata_json.h"
#include "request/request_motions.h"

namespace smpl {
namespace {

namespace fs = std::filesystem;
const std::string kFixtures = SMPL_FIXTURE_DIR;

class RunRequestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "run_request_test_" + std::to_string(::getpid());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    out_ = dir_ + "/body.glb";
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The request the command line makes of `extra` (truncated weights, no
  // refit: the request's path is under test, not the fit; quicker).
  ExportRequest request(std::vector<const char*> extra, const char* model = "builtin") const {
    std::vector<const char*> argv = {"smpl-export",
                                     "--model",
                                     model,
                                     "--out",
                                     out_.c_str(),
                                     "-q",
                                     "--skin-weights",
                                     "truncated",
                                     "--corrective-refit",
                                     "off"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    Result<Settings> s = parseSettings(static_cast<int>(argv.size()), argv.data());
    EXPECT_TRUE(s.ok()) << s.message();
    return s ? s->request : ExportRequest();
  }
  Result<ExportReport> run(const ExportRequest& r) const {
    ModelSource models(r.model);
    return runExportRequest(r, &models);
  }
  std::string producer() const {
    Result<std::vector<uint8_t>> text = readFileBytes(out_ + ".smpl.json");
    return text ? producerHashOf(std::string(text->begin(), text->end())) : "";
  }
  bool exists(const std::string& path) const {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
  }
  std::string dir_, out_;
};

// A NaN the loaders never saw (a model built in code) reaches the asset as a
// morph delta; the job must refuse before writing.
TEST_F(RunRequestTest, NonFiniteAssetIsNotWritten) {
  BodyModel model = demoBody();
  model.posedirs(3 * 7 + 1, 0) = std::numeric_limits<double>::quiet_NaN();
  ExportRequest r = request({});
  r.model = "nan-model";
  ModelSource models(r.model);
  ASSERT_TRUE(models.add(r.model, std::move(model)).ok());
  Result<ExportReport> report = runExportJob(r, RunInputs(), &models);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.kind(), ErrorKind::Export);
  EXPECT_EQ(report.message().rfind("Error exporting " + out_ + ": morph target ", 0), 0u)
      << report.message();
  EXPECT_NE(report.message().find("vertex 7 is not finite (nan)"), std::string::npos)
      << report.message();
  EXPECT_FALSE(exists(out_));
  EXPECT_FALSE(exists(out_ + ".smpl.json"));
}

TEST_F(RunRequestTest, SidecarRecordsWhatProducedTheOutput) {
  auto hashWith = [&](std::vector<const char*> extra) {
    Result<ExportReport> r = run(request(extra));
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

// --model DIR with a motion: the motion file is decoded once (the folder's
// pick reads the decoded motion's gender), and the pick is the female model.
TEST_F(RunRequestTest, EachMotionIsDecodedOnce) {
  const std::string folder = kFixtures + "/released/smpl_folder";
  const std::string f_walk = kFixtures + "/released/mixed_gender/f_walk.npz";
  const std::string m_walk = kFixtures + "/released/mixed_gender/m_walk.npz";
  const uint64_t before = motionsDecoded();
  Result<ExportReport> one = run(request({"--motion", f_walk.c_str()}, folder.c_str()));
  ASSERT_TRUE(one.ok()) << one.message();
  EXPECT_EQ(motionsDecoded() - before, 1u);
  EXPECT_EQ(one->model_path, folder + "/SMPL_FEMALE.pkl");
  Result<ExportReport> two =
      run(request({"--motion", m_walk.c_str(), "--motion", f_walk.c_str()}, folder.c_str()));
  ASSERT_TRUE(two.ok()) << two.message();
  EXPECT_EQ(motionsDecoded() - before, 3u);
  EXPECT_EQ(two->model_path, folder + "/SMPL_MALE.pkl");  // the first motion's gender
  EXPECT_EQ(two->frames, 60);
}

// The pick takes a decoded Motion, not a path: one built in code (no file
// at all) chooses by its layout and gender.
TEST_F(RunRequestTest, FolderPickUsesTheDecodedMotion) {
  ModelSource models(kFixtures + "/released/smpl_folder");
  Motion motion;
  motion.layout = ModelKind::Smpl;
  for (const auto& [gender, file] : std::vector<std::pair<std::string, std::string>>{
           {"male", "SMPL_MALE.pkl"}, {"female", "SMPL_FEMALE.pkl"}, {"", "SMPL_NEUTRAL.npz"}}) {
    motion.gender = gender;
    Result<ModelPick> pick = models.forMotion(&motion);
    ASSERT_TRUE(pick.ok()) << pick.message();
    EXPECT_EQ(fs::path(pick->path).filename().string(), file) << gender;
  }
  Result<ModelPick> none = models.forMotion(nullptr);
  ASSERT_TRUE(none.ok()) << none.message();
  EXPECT_EQ(fs::path(none->path).filename().string(), "SMPL_NEUTRAL.npz");
}

// AMASS's surface_model_type names the body model: a folder picks that kind,
// not the one of the joint layout (an SMPL-X stage-II file that drives SMPL-H).
TEST_F(RunRequestTest, FolderPickFollowsTheNamedModelKind) {
  fs::create_directories(dir_ + "/models");
  fs::copy_file(kFixtures + "/models/smplh_small.npz", dir_ + "/models/SMPLH_NEUTRAL.npz");
  fs::copy_file(kFixtures + "/models/smplx_small.npz", dir_ + "/models/SMPLX_NEUTRAL.npz");
  ModelSource models(dir_ + "/models");
  Motion motion;
  motion.layout = ModelKind::SmplX;
  EXPECT_EQ(fs::path(models.forMotion(&motion)->path).filename(), "SMPLX_NEUTRAL.npz");
  motion.model_kind = ModelKind::SmplH;
  EXPECT_EQ(fs::path(models.forMotion(&motion)->path).filename(), "SMPLH_NEUTRAL.npz");
  Result<Motion> amass = loadMotion(kFixtures + "/formats/subject/run_stageii.npz");
  ASSERT_TRUE(amass.ok()) << amass.message();
  EXPECT_EQ(amass->model_kind, ModelKind::SmplX);  // surface_model_type "smplx"
}

// Motion betas beyond the model's count are not used, and a note says so
// (--betas-file refuses them: the user typed them).
TEST_F(RunRequestTest, MotionBetasBeyondTheModelAreNoted) {
  const std::string model = kFixtures + "/models/smpl_small.npz";
  const std::string motion = kFixtures + "/motions/amass_smplh.npz";  // 16 betas
  Result<ExportReport> r = run(request({"--motion", motion.c_str()}, model.c_str()));
  ASSERT_TRUE(r.ok()) << r.message();
  EXPECT_EQ(r->options.betas.size(), 10u);
  EXPECT_NE(std::find_if(r->notes.begin(), r->notes.end(),
                         [](const std::string& n) {
                           return n.find(
                                      "the motion has 16 betas; the model smpl_small.npz has "
                                      "10: betas 10..15 are not used") != std::string::npos;
                         }),
            r->notes.end());
}

// Ranges that need the model are checked once it is known; nothing is written.
TEST_F(RunRequestTest, ModelChecksRunOnceTheModelIsKnown) {
  Result<ExportReport> r = run(request({"--max-influences", "30"}));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(),
            "Error in arguments: --max-influences must be between 1 and 24 (the model's joints) or "
            "'all', got 30");
  EXPECT_EQ(r.kind(), ErrorKind::Usage);
  EXPECT_FALSE(exists(out_));
  Result<ExportReport> fps = run(request({"--motion", "w.npz", "--fps", "0"}));
  ASSERT_FALSE(fps.ok());  // before the motion is opened
  EXPECT_EQ(fps.message(), "Error in arguments: --fps: expected a rate in (0, 1000], got '0'");
}

TEST_F(RunRequestTest, GuardRunsBeforeAnyWork) {
  const std::string model = dir_ + "/m.glb";
  fs::copy_file(kFixtures + "/models/smpl_small.npz", model);
  ExportRequest r = request({}, model.c_str());
  r.out = model;
  const uint64_t before = motionsDecoded();
  r.motions = {kFixtures + "/motions/smpl_72.npz"};
  Result<ExportReport> report = run(r);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.message(), "Error in arguments: output " + model +
                                  " would overwrite the input " + model +
                                  " (same file); choose another output path");
  EXPECT_EQ(motionsDecoded(), before);
  EXPECT_EQ(fs::file_size(model), fs::file_size(kFixtures + "/models/smpl_small.npz"));
}

// The notes come from what the bake used: the joints the clip's mapping
// dropped and the --frames range clamped to the motion, once each.
TEST_F(RunRequestTest, NotesComeFromTheBake) {
  const std::string walk = kFixtures + "/motions/amass_smplh.npz";
  Result<ExportReport> r = run(request({"--motion", walk.c_str(), "--frames", "0:100000"}));
  ASSERT_TRUE(r.ok()) << r.message();
  const std::vector<std::string>& notes = r->notes;
  auto count = [&](const std::string& text) {
    return std::count_if(notes.begin(), notes.end(),
                         [&](const std::string& n) { return n.find(text) != std::string::npos; });
  };
  EXPECT_EQ(count("amass_smplh: 30 smplh joints not in the model were dropped (left_index1, ...)"),
            1);
  EXPECT_EQ(count("amass_smplh: --frames 0:100000 ends after the motion's"), 1);
  EXPECT_GT(r->frames, 0);
}

// --betas-file is read once per run, its note kept for the summary.
TEST_F(RunRequestTest, BetasFileIsARunInput) {
  const std::string betas = kFixtures + "/released/betas_rows_differ.npy";
  ExportRequest r =
      request({"--betas-file", betas.c_str()}, (kFixtures + "/models/smpl_small.npz").c_str());
  ModelSource models(r.model);
  Result<RunInputs> inputs = loadRunInputs(r, &models);
  ASSERT_TRUE(inputs.ok()) << inputs.message();
  EXPECT_TRUE(inputs->betas_given);
  EXPECT_EQ(inputs->betas.size(), 10u);
  EXPECT_EQ(inputs->betas_note.rfind(betas + ": betas: 30 per-frame rows differ", 0), 0u)
      << inputs->betas_note;
  r.betas_file = dir_ + "/missing.json";
  Result<RunInputs> missing = loadRunInputs(r, &models);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.kind(), ErrorKind::Load);
  EXPECT_EQ(missing.message().rfind("Error loading " + r.betas_file + ": ", 0), 0u)
      << missing.message();
}

// --track all: one output per person, <out stem>.track<ID>.<ext>, the file
// decoded once; --track ID picks one; the sidecar names the track and its
// source frames (docs/file-contract.md "Metadata").
TEST_F(RunRequestTest, TrackAllWritesOneOutputPerPerson) {
  const std::string seq = kFixtures + "/layouts/video/smplerx/smplx";
  const std::string model = kFixtures + "/models/smplx_small.npz";
  ExportRequest r = request({"--motion-sequence", seq.c_str(), "--track", "all"}, model.c_str());
  ModelSource models(r.model);
  const uint64_t before = motionsDecoded();
  Result<std::vector<ExportReport>> reports = runTrackExports(r, &models);
  ASSERT_TRUE(reports.ok()) << reports.message();
  EXPECT_EQ(motionsDecoded() - before, 1u);
  ASSERT_EQ(reports->size(), 2u);
  EXPECT_EQ((*reports)[0].out, dir_ + "/body.track0.glb");
  EXPECT_EQ((*reports)[1].out, dir_ + "/body.track1.glb");
  EXPECT_FALSE(exists(out_));
  Result<std::vector<uint8_t>> text = readFileBytes(dir_ + "/body.track1.glb.smpl.json");
  ASSERT_TRUE(text.ok());
  const std::string sidecar(text->begin(), text->end());
  EXPECT_NE(sidecar.find(R"("track":"1")"), std::string::npos) << sidecar;
  EXPECT_NE(sidecar.find(R"("first_frame":6)"), std::string::npos) << sidecar;
  EXPECT_EQ(trackOutput("a/b.c/walk.fbx", "12"), "a/b.c/walk.track12.fbx");
  EXPECT_EQ(trackOutput("walk", "3"), "walk.track3");
  // An id from the file is one escaped component, never a path.
  EXPECT_EQ(trackOutput("d/walk.glb", "X/../../v"), "d/walk.trackX%2F..%2F..%2Fv.glb");
  EXPECT_EQ(trackOutput("d/walk.glb", ".."), "d/walk.track%2E%2E.glb");
  EXPECT_EQ(trackOutput("d/walk.glb", "a\nb"), "d/walk.tracka%0Ab.glb");
}

TEST_F(RunRequestTest, TrackChoicesAndFoldersAreChecked) {
  const std::string seq = kFixtures + "/layouts/video/smplerx/smplx";
  const std::string model = kFixtures + "/models/smplx_small.npz";
  ExportRequest one = request({"--motion-sequence", seq.c_str(), "--track", "1"}, model.c_str());
  Result<ExportReport> picked = run(one);
  ASSERT_TRUE(picked.ok()) << picked.message();
  EXPECT_NE(std::find_if(picked->notes.begin(), picked->notes.end(),
                         [](const std::string& n) {
                           return n.find("track 1 of 2 (source frames 6-14)") != std::string::npos;
                         }),
            picked->notes.end());
  fs::remove(out_);
  fs::remove(out_ + ".smpl.json");
  ExportRequest none = request({"--motion-sequence", seq.c_str(), "--track", "9"}, model.c_str());
  Result<ExportReport> missing = run(none);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("no track 9 (tracks: 0, 1)"), std::string::npos)
      << missing.message();
  EXPECT_EQ(missing.kind(), ErrorKind::Load);
  const std::string motion = kFixtures + "/motions/smpl_72.npz";
  ExportRequest two =
      request({"--motion", motion.c_str(), "--motion", motion.c_str(), "--track", "all"});
  Result<ExportReport> refused = run(two);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("give one --motion or --motion-sequence"), std::string::npos);
  ExportRequest folder = request({"--motion", seq.c_str()}, model.c_str());
  Result<ExportReport> dir = run(folder);
  ASSERT_FALSE(dir.ok());
  EXPECT_NE(dir.message().find("a folder: give --motion-sequence DIR"), std::string::npos)
      << dir.message();
  EXPECT_FALSE(exists(out_));
}

// A HaMeR left hand on MANO_RIGHT is exported as the model mirrored (the
// job's own copy: the cached model is unchanged), with the note; a right hand
// keeps the model.
TEST_F(RunRequestTest, HandOfTheOtherSidePosesTheMirroredModel) {
  const std::string model = kFixtures + "/models/mano_small.npz";
  const std::string hamer = kFixtures + "/layouts/generation/hamer/";
  for (const char* file : {"left_hand.npz", "right_hand.npz"}) {
    SCOPED_TRACE(file);
    const bool left = std::string(file) == "left_hand.npz";
    const std::string motion = hamer + file;
    ExportRequest r = request({"--motion", motion.c_str()}, model.c_str());
    ModelSource models(r.model);
    Result<ExportReport> report = runExportRequest(r, &models);
    ASSERT_TRUE(report.ok()) << report.message();
    const auto note = std::find_if(report->notes.begin(), report->notes.end(), [](auto& n) {
      return n.find("a left hand on a right MANO model: exported as the mirrored model") !=
             std::string::npos;
    });
    EXPECT_EQ(note != report->notes.end(), left);
    Result<std::vector<uint8_t>> text = readFileBytes(out_ + ".smpl.json");
    ASSERT_TRUE(text.ok());
    const std::string sidecar(text->begin(), text->end());
    EXPECT_EQ(sidecar.find("\"model_name\":\"mano_small.npz (mirrored)\"") != std::string::npos,
              left)
        << sidecar.substr(0, 400);
    Result<ModelPick> cached = models.forMotion(nullptr);
    Result<BodyModel> fresh = loadModel(model);
    ASSERT_TRUE(cached.ok() && fresh.ok());
    EXPECT_EQ(cached->model->name, "mano_small.npz");
    EXPECT_TRUE(cached->model->v_template.isApprox(fresh->v_template, 0));
  }
}

}  // namespace
}  // namespace smpl
