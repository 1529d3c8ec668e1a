// `--model DIR`: pick, from a folder of released model files, the one the
// authors' own loader would pick for a motion's model kind and gender.
//
// Recognised names (case-insensitive, .pkl or .npz), in DIR or in a subfolder
// named after the kind (smpl/, smplh/, smplx/, mano/, as smplx.create() looks
// them up: <dir>/<model_type>/<KIND>_<GENDER>.<ext>):
//   SMPL_{FEMALE,MALE,NEUTRAL}.pkl|npz, SMPLH_*, SMPLX_*, MANO_{RIGHT,LEFT}
//   basicModel_f_lbs_10_207_0_v1.0.0.pkl, basicmodel_m_lbs_10_207_0_v1.0.0.pkl,
//   basicModel_neutral_lbs_10_207_0_v1.0.0.pkl (SMPL 1.0/1.1 release)
//   <kind>/<gender>/model.npz (AMASS's body-model layout, e.g. smplh/male/model.npz)
// Rules: wanted gender, else neutral with a note; when a name exists as both
// .pkl and .npz, the authors' default extension wins (smplx: npz; smpl,
// smplh, mano: pkl); MANO means MANO_RIGHT (smplx.create's default is_rhand),
// or MANO_LEFT for gender "left" (a left-hand motion; MANO_RIGHT with a note
// when the folder has no left model: the export mirrors it).
// Without a wanted kind (no motion), the preference is SMPL-X, SMPL-H, SMPL,
// MANO (the most complete body first), neutral gender.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/result.h"

namespace smpl {

struct ModelFileChoice {
  std::string path;  // relative to the folder, '/'-separated, as listed
  ModelKind kind = ModelKind::Smpl;
  std::string gender;  // "female", "male", "neutral" ("right" for MANO)
  std::string note;    // set when the wanted gender was not there (fell back to neutral)
};

// "female"/"f", "male"/"m", "neutral"/"n"/"" (any case) -> canonical; anything else -> "".
std::string normalizeGender(const std::string& gender);

// Pure: `files` are paths relative to the folder ('/'-separated); `kind`
// empty = no motion; `gender` as a motion stores it ("" = unknown -> neutral).
// Errors name `folder` and list what was found (the model files recognised,
// else every file seen, at most 8).
Result<ModelFileChoice> chooseModelFile(const std::vector<std::string>& files,
                                        std::optional<ModelKind> kind, const std::string& gender,
                                        const std::string& folder);

// Regular files under `dir`, up to two folder levels deep, relative and sorted.
// Symbolic links (to files or to folders) are followed and listed under their
// own names (`smplx/SMPLX_NEUTRAL.npz` for a link smplx -> /shared/smplx); a
// dangling link is listed too, so that picking it fails with its reason.
std::vector<std::string> listModelFolder(const std::string& dir);

}  // namespace smpl
