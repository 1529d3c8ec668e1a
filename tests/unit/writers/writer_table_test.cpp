// The writer table (writers/writer.h) is the one list of output formats: the
// usage text, --format's choices, the --out extension check and where the
// format-only options apply all follow it, a row added for the test
// included; and a row without a mesh (needs_mesh = false, a skeleton-only
// writer such as BVH) makes the request skip the mesh: no skin fitted, no
// morph targets, and the asset check does not ask for a mesh.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli/options.h"
#include "cli/settings.h"
#include "core/io/file_io.h"
#include "request/check_request.h"
#include "request/run_paths.h"
#include "request/run_request.h"
#include "writers/writer.h"

namespace smpl {
namespace {

namespace fs = std::filesystem;

Result<Settings> parse(std::vector<const char*> args) {
  args.insert(args.begin(), "smpl-export");
  return parseSettings(static_cast<int>(args.size()), args.data());
}

std::string joined(const std::vector<std::string>& items, const std::string& sep) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : sep) + item;
  return text;
}

// What the writer was handed, to show what the request built for it.
struct Seen {
  int vertices = -1, influences = -1, morph_targets = -1, clips = -1;
  bool skeleton_only = false;
};
Seen seen;

// A skeleton-only writer: joint names and clip lengths as text.
struct SkeletonWriter : Writer {
  const char* name() const override { return "skel"; }
  Result<std::string> serialize(const Asset& a, const WriterOptions&) const override {
    seen = Seen{static_cast<int>(a.mesh.positions.rows()), static_cast<int>(a.mesh.joints.cols()),
                static_cast<int>(a.mesh.morph_targets.size()),
                static_cast<int>(a.animations.size()), a.skeleton_only};
    std::string text = "joints";
    for (const std::string& n : a.skeleton.names) text += " " + n;
    for (const AnimationClip& c : a.animations)
      text += "\nclip " + c.name + " " + std::to_string(c.times.size());
    return text + "\n";
  }
};

WriterFormat skeletonRow() {
  static const SkeletonWriter writer;
  WriterFormat row;
  row.name = "skel";
  row.extensions = {".skel"};
  row.needs_mesh = false;
  row.writer = &writer;
  return row;
}

// Everything the command line says about formats, checked against the table.
// The usage text with each run of blanks and line breaks as one space: a
// list the 80-column help wraps reads as one phrase.
std::string flat(const std::string& text) {
  std::string out;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += c;
    else if (!out.empty() && out.back() != ' ')
      out += ' ';
  return out;
}

void expectTheCommandLineFollows(const std::string& usage) {
  std::vector<std::string> names, extensions;
  for (const WriterFormat& row : writerFormats()) {
    names.push_back(row.name);
    extensions.insert(extensions.end(), row.extensions.begin(), row.extensions.end());
  }
  const std::string format = "  --format " + joined(names, "|");
  const size_t at = usage.find(format);
  ASSERT_NE(at, std::string::npos) << usage;
  EXPECT_TRUE(std::isspace(static_cast<unsigned char>(usage[at + format.size()]))) << usage;
  EXPECT_NE(usage.find("--out FILE" + joined(extensions, "|") + " [options]"), std::string::npos);
  EXPECT_NE(flat(usage).find("(" + joined(extensions, ", ") + ")"), std::string::npos);
  for (const WriterFormat& row : writerFormats()) {
    Result<Settings> batch = parse({"--model", "builtin", "--motion-dir", "m", "--out-dir", "o",
                                    "--format", row.name.c_str()});
    ASSERT_TRUE(batch.ok()) << row.name << ": " << batch.message();
    // A format that holds no animation refuses batch mode: its motions would be lost
    // (every real row is animated now; AStaticRowRefusesMotions checks such a row).
    EXPECT_EQ(checkRequest(batch->request).ok(), row.animated)
        << row.name << ": " << checkRequest(batch->request).message();
    for (const std::string& ext : row.extensions) {
      ExportRequest r;
      r.model = "builtin";
      r.out = "a" + ext;
      EXPECT_TRUE(checkRequest(r).ok()) << ext << ": " << checkRequest(r).message();
      EXPECT_EQ(writerFormatForPath("DIR/A" + ext), &row);  // any case
      for (const std::string& option : row.options) {       // the row's format-only options apply
        const OptionSpec* o = findOption(option);
        ASSERT_NE(o, nullptr) << option;
        EXPECT_EQ(o->applies, Applies::Format) << option;
        std::vector<const char*> args = {"--model", "builtin", "--out", r.out.c_str(), o->name};
        const std::map<std::string, const char*> values = {
            {"--fbx-units", "cm"},          {"--fbx-version", "7500"}, {"--bvh-units", "cm"},
            {"--skeleton-names", "mixamo"}, {"--mjcf-joints", "ball"}, {"--mjcf-geoms", "mesh"}};
        if (o->value) args.push_back(values.count(option) ? values.at(option) : "1");
        Result<Settings> s = parse(args);
        EXPECT_TRUE(s.ok()) << option << " on " << ext << ": " << s.message();
      }
    }
  }
  ExportRequest unknown;
  unknown.model = "builtin";
  unknown.out = "a.obj";
  EXPECT_EQ(checkRequest(unknown).message(),
            "--out a.obj: unknown format (expected " + writerExtensionList() + ")");
}

TEST(WriterTable, CommandLineFollowsTheTable) {
  ASSERT_EQ(writerFormats().size(), 7u);
  EXPECT_EQ(writerExtensionList(), ".glb, .gltf, .fbx, .bvh, .xml, .usda, .usd or .usdz");
  expectTheCommandLineFollows(usageText());
  EXPECT_EQ(writerForPath("x.FBX"), writerFormatByName("fbx")->writer);
}

TEST(WriterTable, ARowAddedIsOfferedEverywhere) {
  {
    ScopedWriterFormat skel(skeletonRow());
    const std::string usage = usageText();
    EXPECT_NE(usage.find("--format glb|gltf|fbx|bvh|mjcf|usda|usdz|skel"), std::string::npos)
        << usage;
    EXPECT_NE(flat(usage).find("(.glb, .gltf, .fbx, .bvh, .xml, .usda, .usd, .usdz, .skel)"),
              std::string::npos)
        << usage;
    expectTheCommandLineFollows(usage);
    // the glTF/FBX-only options do not apply to it
    Result<Settings> draco = parse({"--model", "builtin", "--out", "a.skel", "--draco"});
    ASSERT_FALSE(draco.ok());
    EXPECT_EQ(draco.message(), "--draco applies only to .glb, .gltf output");
  }
  Result<Settings> gone =
      parse({"--model", "builtin", "--motion-dir", "m", "--out-dir", "o", "--format", "skel"});
  ASSERT_TRUE(gone.ok()) << gone.message();  // the parser stores it; the request checks it
  EXPECT_EQ(checkRequest(gone->request).message(),
            "--format: expected 'glb', 'gltf', 'fbx', 'bvh', 'mjcf', 'usda' or 'usdz', got 'skel'");
  EXPECT_EQ(writerFormatForPath("a.skel"), nullptr);
}

TEST(WriterTable, MjcfRowWritesTheMotionBesideTheXml) {
  const WriterFormat* mjcf = writerFormatByName("mjcf");
  ASSERT_NE(mjcf, nullptr);
  EXPECT_TRUE(mjcf->animated);
  EXPECT_TRUE(mjcf->single_clip);
  ExportRequest r;
  r.model = "builtin";
  r.out = "DIR/body.XML";
  EXPECT_EQ(gltfBufferPath(r, r.out), "");  // no motion: the XML alone
  r.motions = {"walk.npz"};
  EXPECT_EQ(gltfBufferPath(r, r.out), "DIR/body.qpos.npz");
  EXPECT_TRUE(checkRequest(r).ok()) << checkRequest(r).message();
  r.motions = {"walk.npz", "run.npz"};
  EXPECT_EQ(checkRequest(r).message(),
            "--motion: mjcf output holds one motion; got 2 (one output per motion: --motion-dir)");
  r.motions.clear();
  r.motion_dir = "m";  // batch: every output has a motion
  EXPECT_EQ(gltfBufferPath(r, "DIR/walk.xml"), "DIR/walk.qpos.npz");
  r.out = "DIR/body.glb";
  EXPECT_EQ(gltfBufferPath(r, r.out), "");
  // The motion options apply to .xml as to the other animated formats.
  Result<Settings> s = parse({"--model", "builtin", "--motion", "walk.npz", "--out", "a.xml",
                              "--fps", "30", "--frames", "0:10", "--root-motion", "in-place"});
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(checkRequest(s->request).ok()) << checkRequest(s->request).message();
}

TEST(WriterTable, AStaticRowRefusesMotions) {
  WriterFormat row = skeletonRow();
  row.name = "still";
  row.extensions = {".still"};
  row.animated = false;
  ScopedWriterFormat still(row);
  ExportRequest r;
  r.model = "builtin";
  r.out = "a.still";
  EXPECT_TRUE(checkRequest(r).ok()) << checkRequest(r).message();
  r.motions = {"walk.npz"};
  EXPECT_EQ(checkRequest(r).message(),
            "--motion: still output holds no animation (the model only)");
}

TEST(WriterTable, RowWithoutAMeshSkipsSkinAndMorphs) {
  ScopedWriterFormat skel(skeletonRow());
  const std::string dir = ::testing::TempDir() + "writer_table_" + std::to_string(::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  ExportRequest r;
  r.model = "builtin";
  r.out = dir + "/walk.skel";
  r.motions = {std::string(SMPL_FIXTURE_DIR) + "/motions/smpl_72.npz"};
  r.skin_error_poses = 32;  // asked, but there is no skin to measure
  ModelSource models(r.model);
  seen = Seen();
  Result<ExportReport> report = runExportRequest(r, &models);
  ASSERT_TRUE(report.ok()) << report.message();
  EXPECT_FALSE(report->skin_fitted);
  EXPECT_FALSE(report->skin_error_measured);
  EXPECT_EQ(report->skin.joints.size(), 0);
  EXPECT_EQ(report->vertices, 0);
  EXPECT_EQ(report->morph_targets, 0);
  EXPECT_EQ(report->joints, 24);
  EXPECT_EQ(report->frames, 60);
  EXPECT_TRUE(seen.skeleton_only);
  EXPECT_EQ(seen.vertices, 0);
  EXPECT_EQ(seen.influences, 0);
  EXPECT_EQ(seen.morph_targets, 0);
  EXPECT_EQ(seen.clips, 1);
  Result<std::vector<uint8_t>> bytes = readFileBytes(r.out);
  ASSERT_TRUE(bytes.ok()) << bytes.message();
  const std::string text(bytes->begin(), bytes->end());
  EXPECT_EQ(text.rfind("joints pelvis left_hip", 0), 0u) << text;
  EXPECT_NE(text.find("\nclip smpl_72 60\n"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(r.out + ".smpl.json"));
  // What only a mesh has is refused for it, before any work.
  r.asset.shape_keys = 2;
  Result<ExportReport> keys = runExportRequest(r, &models);
  ASSERT_FALSE(keys.ok());
  EXPECT_EQ(keys.message(),
            "Error in arguments: --shape-keys needs an output format with a mesh; skel output has "
            "none");
  ExportRequest batch;  // a batch in that format: refused up front, not per motion
  batch.model = "builtin";
  batch.motion_dir = dir;
  batch.format = "skel";
  batch.dmpl = "d.npz";
  EXPECT_EQ(checkRequest(batch).message(),
            "--dmpl needs an output format with a mesh; skel output has none");
  // The same request for a row with a mesh fits a skin.
  r.asset.shape_keys = 0;
  r.out = dir + "/walk.glb";
  r.skin_error_poses = 0;
  Result<ExportReport> glb = runExportRequest(r, &models);
  ASSERT_TRUE(glb.ok()) << glb.message();
  EXPECT_TRUE(glb->skin_fitted);
  EXPECT_GT(glb->vertices, 0);
  EXPECT_GT(glb->morph_targets, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace smpl
