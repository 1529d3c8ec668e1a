// --skeleton-names: the table covers every SMPL-family joint, its bone names
// are unique per rig, smpl is the identity, and an export renames the bones
// only (morph target names and every number as with the model's names), with
// the model's names and the bones' in the metadata.
#include "exporter/skeleton_names.h"

#include <gtest/gtest.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <set>

#include "core/joint_names.h"
#include "core/models/model_loader.h"
#include "exporter/export_asset.h"
#include "exporter/metadata_json.h"

namespace smpl {
namespace {

const std::string kFixtures = std::string(SMPL_FIXTURE_DIR);
const SkeletonNames kRigs[] = {SkeletonNames::Mixamo, SkeletonNames::Ue5};
const ModelKind kBodies[] = {ModelKind::Smpl, ModelKind::SmplH, ModelKind::SmplX};

TEST(SkeletonNames, EveryBodyJointHasOneRowAndNoOtherRows) {
  std::set<std::string> joints;
  for (ModelKind kind : kBodies)
    for (const std::string& j : canonicalJointNames(kind)) joints.insert(j);
  std::set<std::string> rows;
  for (const SkeletonNameRow& row : skeletonNameTable()) {
    EXPECT_TRUE(rows.insert(row.joint).second) << "two rows for " << row.joint;
    EXPECT_EQ(joints.count(row.joint), 1u) << row.joint << " is no SMPL-family joint";
  }
  EXPECT_EQ(rows, joints);
  EXPECT_EQ(rows.size(), 57u);  // 22 body, 2 SMPL hand ends, jaw, 2 eyes, 30 finger joints
}

TEST(SkeletonNames, BoneNamesAreUniquePerRigAndModel) {
  for (SkeletonNames rig : kRigs) {
    std::set<std::string> column;  // the whole column: each rig bone once
    for (const SkeletonNameRow& row : skeletonNameTable()) {
      const char* bone = rig == SkeletonNames::Mixamo ? row.mixamo : row.ue5;
      if (bone) {
        EXPECT_TRUE(column.insert(bone).second) << bone << " twice";
      }
    }
    for (ModelKind kind : kBodies) {  // with the kept model names, per model
      std::set<std::string> bones;
      for (const std::string& j : canonicalJointNames(kind))
        EXPECT_TRUE(bones.insert(boneNameOf(j, rig)).second)
            << skeletonNamesName(rig) << " " << modelKindName(kind) << ": " << j;
    }
  }
}

TEST(SkeletonNames, SmplIsTheIdentityAndRigNamesHaveTheRigsForm) {
  for (ModelKind kind : kBodies)
    for (const std::string& j : canonicalJointNames(kind))
      EXPECT_EQ(boneNameOf(j, SkeletonNames::Smpl), j);
  EXPECT_EQ(boneNameOf("root", SkeletonNames::Mixamo), "root");  // --root-bone's joint
  for (const SkeletonNameRow& row : skeletonNameTable()) {
    if (row.mixamo) {
      EXPECT_EQ(std::string(row.mixamo).rfind("mixamorig:", 0), 0u) << row.mixamo;
    }
    for (char c : std::string(row.ue5 ? row.ue5 : "")) {
      EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) ||
                  std::isdigit(static_cast<unsigned char>(c)) || c == '_')
          << row.ue5;
    }
    // a joint without a bone keeps its name on both rigs
    EXPECT_EQ(boneNameOf(row.joint, SkeletonNames::Mixamo), row.mixamo ? row.mixamo : row.joint);
    EXPECT_EQ(boneNameOf(row.joint, SkeletonNames::Ue5), row.ue5 ? row.ue5 : row.joint);
  }
  // rows spelled out (docs/retargeting.md): a wrong column or row would show here
  EXPECT_EQ(boneNameOf("left_hip", SkeletonNames::Mixamo), "mixamorig:LeftUpLeg");
  EXPECT_EQ(boneNameOf("left_foot", SkeletonNames::Mixamo), "mixamorig:LeftToeBase");
  EXPECT_EQ(boneNameOf("right_collar", SkeletonNames::Mixamo), "mixamorig:RightShoulder");
  EXPECT_EQ(boneNameOf("right_shoulder", SkeletonNames::Mixamo), "mixamorig:RightArm");
  EXPECT_EQ(boneNameOf("spine3", SkeletonNames::Mixamo), "mixamorig:Spine2");
  EXPECT_EQ(boneNameOf("left_thumb1", SkeletonNames::Mixamo), "mixamorig:LeftHandThumb1");
  EXPECT_EQ(boneNameOf("left_hand", SkeletonNames::Mixamo), "left_hand");
  EXPECT_EQ(boneNameOf("jaw", SkeletonNames::Ue5), "jaw");
  EXPECT_EQ(boneNameOf("spine2", SkeletonNames::Ue5), "spine_03");
  EXPECT_EQ(boneNameOf("right_foot", SkeletonNames::Ue5), "ball_r");
  EXPECT_EQ(boneNameOf("right_pinky3", SkeletonNames::Ue5), "pinky_03_r");
}

Result<Asset> exported(const BodyModel& model, const Motion& motion, SkeletonNames names,
                       bool root_bone = false) {
  ExportOptions o;
  o.skeleton_names = names;
  o.root_bone = root_bone;
  return exportAsset(model, o, {{&motion, "walk.npz", {}, nullptr}});
}

// Only Skeleton::names differs from the smpl export; the metadata keeps the
// model's joint_names (what pose_<joint>_<rc> names) and adds the bones'.
TEST(SkeletonNames, AnExportRenamesTheBonesOnly) {
  for (const char* kind : {"smplh", "smplx"}) {
    Result<BodyModel> model = loadModel(kFixtures + "/models/" + kind + "_small.npz");
    ASSERT_TRUE(model.ok()) << model.message();
    Result<Motion> motion = loadMotion(kFixtures + "/motions/amass_" + kind + ".npz");
    ASSERT_TRUE(motion.ok()) << motion.message();
    for (bool root_bone : {false, true}) {
      Result<Asset> smpl = exported(*model, *motion, SkeletonNames::Smpl, root_bone);
      ASSERT_TRUE(smpl.ok()) << smpl.message();
      const nlohmann::json plain = nlohmann::json::parse(metadataJson(*smpl));
      EXPECT_EQ(plain.count("skeleton_names"), 0u);
      EXPECT_EQ(plain.count("bone_names"), 0u);
      for (SkeletonNames rig : kRigs) {
        Result<Asset> renamed = exported(*model, *motion, rig, root_bone);
        ASSERT_TRUE(renamed.ok()) << renamed.message();
        const size_t first = root_bone ? 1 : 0;
        ASSERT_EQ(renamed->skeleton.names.size(), smpl->skeleton.names.size());
        if (root_bone) {
          EXPECT_EQ(renamed->skeleton.names[0], "root");
        }
        for (size_t k = first; k < smpl->skeleton.names.size(); ++k)
          EXPECT_EQ(renamed->skeleton.names[k], boneNameOf(smpl->skeleton.names[k], rig));
        EXPECT_EQ(renamed->skeleton.names[first],
                  rig == SkeletonNames::Mixamo ? "mixamorig:Hips" : "pelvis");
        EXPECT_EQ(renamed->skeleton.parents, smpl->skeleton.parents);
        EXPECT_EQ(renamed->skeleton.rest_local, smpl->skeleton.rest_local);
        EXPECT_EQ(renamed->mesh.positions, smpl->mesh.positions);
        EXPECT_EQ(renamed->mesh.weights, smpl->mesh.weights);
        ASSERT_EQ(renamed->mesh.morph_targets.size(), smpl->mesh.morph_targets.size());
        for (size_t t = 0; t < smpl->mesh.morph_targets.size(); ++t)
          EXPECT_EQ(renamed->mesh.morph_targets[t].name, smpl->mesh.morph_targets[t].name);
        ASSERT_EQ(renamed->animations.size(), 1u);
        EXPECT_EQ(renamed->animations[0].root_translation, smpl->animations[0].root_translation);
        EXPECT_EQ(renamed->animations[0].morph_weights, smpl->animations[0].morph_weights);
        for (size_t k = 0; k < smpl->animations[0].rotations.size(); ++k)
          for (size_t t = 0; t < smpl->animations[0].rotations[k].size(); ++t)
            EXPECT_EQ(renamed->animations[0].rotations[k][t].coeffs(),
                      smpl->animations[0].rotations[k][t].coeffs());
        nlohmann::json meta = nlohmann::json::parse(metadataJson(*renamed));
        EXPECT_EQ(meta["skeleton_names"], skeletonNamesName(rig));
        EXPECT_EQ(meta["joint_names"], plain["joint_names"]);  // the model's names
        EXPECT_EQ(meta["parents"], plain["parents"]);
        ASSERT_EQ(meta["bone_names"].size(), plain["joint_names"].size());
        for (size_t k = 0; k < meta["bone_names"].size(); ++k)
          EXPECT_EQ(meta["bone_names"][k],
                    boneNameOf(plain["joint_names"][k].get<std::string>(), rig));
        // everything else as with the model's names (the root bone's child is the file's bone)
        meta.erase("skeleton_names");
        meta.erase("bone_names");
        nlohmann::json same = plain;
        if (root_bone) same["root_bone"]["child"] = renamed->skeleton.names[1];
        EXPECT_EQ(meta, same);
      }
    }
  }
}

}  // namespace
}  // namespace smpl
