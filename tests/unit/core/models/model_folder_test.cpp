// --model DIR: the file the authors' loaders would pick, from listings in the
// released layouts (pure function: no files needed).
#include "core/models/model_folder.h"

#include <gtest/gtest.h>

namespace smpl {
namespace {

std::string pick(const std::vector<std::string>& files, std::optional<ModelKind> kind,
                 const std::string& gender, std::string* note = nullptr) {
  Result<ModelFileChoice> c = chooseModelFile(files, kind, gender, "models");
  if (!c) return "error: " + c.message();
  if (note) *note = c->note;
  return c->path;
}

TEST(ModelFolder, SmplReleaseNamesByGender) {
  const std::vector<std::string> files = {"SMPL_FEMALE.pkl", "SMPL_MALE.pkl", "SMPL_NEUTRAL.pkl",
                                          "readme.txt"};
  EXPECT_EQ(pick(files, ModelKind::Smpl, "female"), "SMPL_FEMALE.pkl");
  EXPECT_EQ(pick(files, ModelKind::Smpl, "male"), "SMPL_MALE.pkl");
  EXPECT_EQ(pick(files, ModelKind::Smpl, "m"), "SMPL_MALE.pkl");
  EXPECT_EQ(pick(files, ModelKind::Smpl, ""), "SMPL_NEUTRAL.pkl");
  EXPECT_EQ(pick(files, std::nullopt, ""), "SMPL_NEUTRAL.pkl");
}

TEST(ModelFolder, BasicModelNamesOfTheSmpl10Release) {
  const std::vector<std::string> files = {"basicModel_f_lbs_10_207_0_v1.0.0.pkl",
                                          "basicmodel_m_lbs_10_207_0_v1.0.0.pkl",
                                          "basicModel_neutral_lbs_10_207_0_v1.0.0.pkl"};
  EXPECT_EQ(pick(files, ModelKind::Smpl, "female"), files[0]);
  EXPECT_EQ(pick(files, ModelKind::Smpl, "MALE"), files[1]);
  EXPECT_EQ(pick(files, ModelKind::Smpl, "neutral"), files[2]);
}

TEST(ModelFolder, KindSubfoldersAndTheAuthorsExtension) {
  // smplx.create(model_path, model_type): <dir>/<model_type>/<KIND>_<GENDER>.<ext>; smplx defaults
  // to npz, smpl/smplh/mano to pkl.
  const std::vector<std::string> files = {"smpl/SMPL_NEUTRAL.npz",   "smpl/SMPL_NEUTRAL.pkl",
                                          "smplh/SMPLH_MALE.pkl",    "smplx/SMPLX_NEUTRAL.pkl",
                                          "smplx/SMPLX_NEUTRAL.npz", "smplx/SMPLX_FEMALE.npz",
                                          "mano/MANO_LEFT.pkl",      "mano/MANO_RIGHT.pkl"};
  EXPECT_EQ(pick(files, ModelKind::Smpl, "neutral"), "smpl/SMPL_NEUTRAL.pkl");
  EXPECT_EQ(pick(files, ModelKind::SmplX, "neutral"), "smplx/SMPLX_NEUTRAL.npz");
  EXPECT_EQ(pick(files, ModelKind::SmplX, "female"), "smplx/SMPLX_FEMALE.npz");
  EXPECT_EQ(pick(files, ModelKind::SmplH, "male"), "smplh/SMPLH_MALE.pkl");
  EXPECT_EQ(pick(files, ModelKind::Mano, ""), "mano/MANO_RIGHT.pkl");
  EXPECT_EQ(pick(files, ModelKind::Mano, "left"), "mano/MANO_LEFT.pkl");  // a left hand (HaMeR)
  Result<ModelFileChoice> right =
      chooseModelFile({"mano/MANO_RIGHT.pkl"}, ModelKind::Mano, "left", "M");
  ASSERT_TRUE(right.ok()) << right.message();  // mirrored by the export (hand_side.h)
  EXPECT_EQ(right->path, "mano/MANO_RIGHT.pkl");
  EXPECT_NE(right->note.find("no MANO_LEFT model in M"), std::string::npos) << right->note;
  EXPECT_EQ(pick(files, std::nullopt, "female"),
            "smplx/SMPLX_FEMALE.npz");  // no motion kind: SMPL-X first
}

TEST(ModelFolder, AmassBodyModelLayout) {
  const std::vector<std::string> files = {"smplh/female/model.npz", "smplh/male/model.npz",
                                          "smplh/neutral/model.npz", "dmpls/male/model.npz"};
  EXPECT_EQ(pick(files, ModelKind::SmplH, "female"), "smplh/female/model.npz");
  EXPECT_EQ(pick(files, ModelKind::SmplH, "male"), "smplh/male/model.npz");
  EXPECT_EQ(pick(files, std::nullopt, ""), "smplh/neutral/model.npz");
}

TEST(ModelFolder, MissingGenderFallsBackToNeutralWithANote) {
  std::string note;
  const std::vector<std::string> files = {"SMPLX_NEUTRAL.npz", "SMPLX_FEMALE.npz"};
  EXPECT_EQ(pick(files, ModelKind::SmplX, "male", &note), "SMPLX_NEUTRAL.npz");
  EXPECT_EQ(note, "no male SMPL-X model in models; using SMPLX_NEUTRAL.npz");
  EXPECT_EQ(pick(files, ModelKind::SmplX, "robot", &note), "SMPLX_NEUTRAL.npz");
  EXPECT_EQ(note, "gender 'robot' is not female, male or neutral; using SMPLX_NEUTRAL.npz");
  EXPECT_EQ(pick(files, ModelKind::SmplX, "female", &note), "SMPLX_FEMALE.npz");
  EXPECT_EQ(note, "");
}

TEST(ModelFolder, ErrorsNameTheFolderAndWhatWasFound) {
  EXPECT_EQ(
      pick({"SMPLH_FEMALE.pkl"}, ModelKind::SmplH, "male"),
      "error: models: no male SMPL-H model (e.g. smplh/SMPLH_NEUTRAL.pkl); found SMPLH_FEMALE.pkl");
  EXPECT_EQ(
      pick({"SMPLX_NEUTRAL.npz"}, ModelKind::Smpl, ""),
      "error: models: no neutral SMPL model (e.g. smpl/SMPL_NEUTRAL.pkl); found SMPLX_NEUTRAL.npz");
  EXPECT_EQ(pick({"notes.txt", "my_smplx.npz"}, std::nullopt, ""),
            "error: models: no model files with the released names (e.g. SMPLX_NEUTRAL.npz, "
            "SMPL_FEMALE.pkl); files seen: notes.txt, my_smplx.npz");
  EXPECT_EQ(pick({}, std::nullopt, ""),
            "error: models: no model files with the released names (e.g. SMPLX_NEUTRAL.npz, "
            "SMPL_FEMALE.pkl); no files in it or its subfolders");
}

}  // namespace
}  // namespace smpl
