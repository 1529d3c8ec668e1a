// The motion reader table (core/motions/motion_layout.h): what is derived from
// it (detection order, lazy keys, batch extensions, the messages for files no
// row reads). Fixtures: tests/fixtures/make_table_cases.py.
#include "core/motions/motion_layout.h"

#include <gtest/gtest.h>

#include <set>

#include "core/docs_location.h"
#include "core/motions/motion.h"
#include "core/motions/motion_read.h"

namespace smpl {
namespace {

const std::string kTable = std::string(SMPL_FIXTURE_DIR) + "/table/";

DataNode names(std::initializer_list<const char*> keys) {
  DataNode root;
  root.kind = DataNode::Kind::Dict;
  for (const char* k : keys) root.keys.push_back(k);
  root.children.resize(root.keys.size());
  return root;
}

// The shapes a file holding exactly `keys` can have: a flat dict (an .npz's
// member names, or dicts of them), one track of a dict keyed by id (WHAM,
// VIBE, PHALP), one person of a list (EasyMocap).
std::vector<DataNode> shapesOf(const std::vector<std::string>& keys) {
  DataNode flat;
  flat.kind = DataNode::Kind::Dict;
  flat.keys = keys;
  flat.children.resize(keys.size());
  DataNode dicts = flat;
  for (DataNode& c : dicts.children) c.kind = DataNode::Kind::Dict;
  DataNode by_id;
  by_id.kind = DataNode::Kind::Dict;
  by_id.keys = {"0"};
  by_id.children = {flat};
  DataNode list;
  list.kind = DataNode::Kind::List;
  list.children = {flat};
  return {flat, dicts, by_id, list};
}

// {"scenes": [{"extensions": {"MC_scene_description": {}}}]}: a Meshcapade scene.
DataNode mcsShape() {
  DataNode desc;
  desc.kind = DataNode::Kind::Dict;
  DataNode ext;
  ext.kind = DataNode::Kind::Dict;
  ext.keys = {"MC_scene_description"};
  ext.children = {desc};
  DataNode scene;
  scene.kind = DataNode::Kind::Dict;
  scene.keys = {"extensions"};
  scene.children = {ext};
  DataNode scenes;
  scenes.kind = DataNode::Kind::List;
  scenes.children = {scene};
  DataNode root;
  root.kind = DataNode::Kind::Dict;
  root.keys = {"scenes"};
  root.children = {scenes};
  return root;
}

TEST(MotionLayouts, RowsAreNamedOnceAndReadWhatTheyMatch) {
  std::set<std::string> seen;
  for (const MotionLayout& row : motionLayouts()) {
    EXPECT_TRUE(seen.insert(row.name).second) << row.name;
    EXPECT_NE(row.containers, 0u) << row.name;
    if (row.keys.empty()) {  // a row that reads a root array (Motion-X, bare poses), never a
                             // dict's keys: an .npz or JSON root is never one array
      EXPECT_NE(row.containers & kNpyFile, 0u) << row.name;
      EXPECT_EQ(row.containers & (kNpzFile | kJsonFile), 0u) << row.name;
      continue;
    }
    // A file holding exactly the row's keys is that row's (nothing earlier steals it).
    // The .mcs row decides by a nested path (scenes[0].extensions.MC_scene_description):
    // its shape is built here.
    std::vector<DataNode> shapes = shapesOf(row.keys);
    if (std::string(row.name) == "mcs") shapes.push_back(mcsShape());
    bool matched = false;
    for (const DataNode& root : shapes) {
      if (!row.matches(root)) continue;
      matched = true;
      const MotionLayout* found = findLayout(root, row.containers & -row.containers);
      ASSERT_NE(found, nullptr) << row.name;
      EXPECT_STREQ(found->name, row.name);
    }
    EXPECT_TRUE(matched) << row.name << " matches none of the shapes of its own keys";
  }
}

TEST(MotionLayouts, TableOrderDecides) {
  EXPECT_STREQ(findLayout(names({"bodyPose", "poses"}), kNpzFile)->name, "smplcodec");
  EXPECT_STREQ(findLayout(names({"poses", "body_pose"}), kNpzFile)->name, "amass");
  EXPECT_STREQ(findLayout(names({"global_orient"}), kPickleFile)->name, "fit");
  EXPECT_EQ(findLayout(names({"betas", "gender"}), kNpzFile), nullptr);
  // SMPLCodec comes only as an .npz (.smpl): its keys in a pickle match no row.
  EXPECT_EQ(findLayout(names({"bodyPose"}), kPickleFile), nullptr);
  Result<Motion> m = loadMotion(kTable + "both_keys.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->source_layout, "smplcodec");
  EXPECT_EQ(m->fps, 24.0);
}

TEST(MotionLayouts, OnlyTheMatchedRowsKeysAreDecoded) {
  // `body_pose` is another row's key and is not an .npy at all.
  Result<Motion> m = loadMotion(kTable + "amass_bad_fit_key.npz");
  ASSERT_TRUE(m.ok()) << m.message();
  EXPECT_EQ(m->source_layout, "amass");
  EXPECT_EQ(m->frames.size(), 5u);
  EXPECT_EQ(m->fps, 50.0);
}

TEST(MotionLayouts, APoseKeyHoldingADictIsRefused) {
  Result<Motion> m = loadMotion(kTable + "fit_hand_dict.pkl");
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.message().find("'left_hand_pose' holds dict with keys 'pose', expected an array of "
                             "poses"),
            std::string::npos)
      << m.message();
}

TEST(MotionLayouts, BatchExtensionsComeFromTheContainers) {
  const std::vector<std::string> ext = motionFileExtensions();
  EXPECT_EQ(std::set<std::string>(ext.begin(), ext.end()),
            (std::set<std::string>{".npz", ".smpl", ".pkl", ".joblib", ".pt", ".pth", ".npy",
                                   ".json", ".mcs"}));
}

TEST(MotionLayouts, ShapeFilesAndUnknownLayoutsAreToldApart) {
  EXPECT_TRUE(isShapeOnly(names({"betas", "gender", "surface_model_type"})));
  EXPECT_FALSE(isShapeOnly(names({"pred_cam", "pred_mano_params"})));  // no betas: unknown
  EXPECT_FALSE(isShapeOnly(names({"betas", "pred_rotmat"})));
  Result<Motion> shape = loadMotion(kTable + "shape_only.npz");
  ASSERT_FALSE(shape.ok());
  EXPECT_NE(shape.message().find("no pose data (keys betas, gender)"), std::string::npos)
      << shape.message();
  for (const char* file : {"unknown_layout.npz", "unknown_layout.pkl"}) {
    Result<Motion> m = loadMotion(kTable + file);
    ASSERT_FALSE(m.ok()) << file;
    EXPECT_EQ(m.message().find("shape file"), std::string::npos) << m.message();
    EXPECT_NE(m.message().find("keys found: "), std::string::npos) << m.message();
    EXPECT_NE(m.message().find("pred_rotmat, pred_shape; supported layouts"), std::string::npos)
        << m.message();
    EXPECT_NE(m.message().find("; supported layouts: motions.md in the smpl-export documentation"),
              std::string::npos)
        << m.message();
    setDocsFolder("/opt/se/share/doc/smpl-export");  // as the CLI sets it from its executable
    Result<Motion> located = loadMotion(kTable + file);
    setDocsFolder("");
    ASSERT_FALSE(located.ok());
    EXPECT_NE(
        located.message().find("; supported layouts: motions.md in /opt/se/share/doc/smpl-export"),
        std::string::npos)
        << located.message();
    Result<bool> poses = hasPoseData(kTable + file);  // batch mode fails it, never skips it
    ASSERT_TRUE(poses.ok()) << poses.message();
    EXPECT_TRUE(*poses) << file;
  }
  Result<bool> poses = hasPoseData(kTable + "shape_only.npz");
  ASSERT_TRUE(poses.ok());
  EXPECT_FALSE(*poses);
  EXPECT_NE(shape.message().find("a shape file, not a motion: give it as --betas-file"),
            std::string::npos)
      << shape.message();
}

// A model given as --motion is named as one, with the option that takes it.
TEST(MotionLayouts, AModelFileIsToldToGoToModel) {
  EXPECT_TRUE(isBodyModel(names({"J_regressor", "f", "posedirs", "shapedirs", "v_template"})));
  EXPECT_FALSE(isBodyModel(names({"v_template", "poses"})));  // a template alone: not a model
  EXPECT_FALSE(isBodyModel(names({"posedirs", "weights"})));
  const std::string models = std::string(SMPL_FIXTURE_DIR) + "/models/";
  for (const char* file : {"smpl_small.npz", "smplh_small_p2.pkl"}) {
    Result<Motion> m = loadMotion(models + file);
    ASSERT_FALSE(m.ok()) << file;
    EXPECT_NE(m.message().find("a body model file (keys "), std::string::npos) << m.message();
    EXPECT_NE(m.message().find("not a motion: give it as --model"), std::string::npos)
        << m.message();
  }
}

}  // namespace
}  // namespace smpl
