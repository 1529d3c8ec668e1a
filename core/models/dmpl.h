// DMPL (Dynamic SMPL) soft-tissue basis: the dynamic blend shapes AMASS ships
// beside the SMPL-H model (an .npz per gender, key `eigvec`, shape (N,3,D),
// D = 8 in the public release). A motion's per-frame coefficients `dmpls`
// (T,D) (core/motions/motion.h) weight the directions; in the AMASS body model
// code (human_body_prior BodyModel.forward) the displacement eigvec * dmpls is
// added to the shaped template before posing, and the joints are regressed
// from the displaced template.
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/memory_budget.h"
#include "core/result.h"

namespace smpl {

struct DmplBasis {
  std::string path;  // the file read (for notes and errors)
  Eigen::MatrixXd
      directions;       // 3N x D, row 3i + c = vertex i, axis c (metres per unit coefficient)
  MemoryCharge charge;  // `directions` against the memory budget
};

// Reads `eigvec` (N,3,D) from `path` and keeps the first `count` directions
// (0 = all). Errors (one line naming `path`): unreadable file, not an .npz in
// a regular file or over 1 GiB (kDmplInput, core/io/input_kind.h), no
// `eigvec`, shape not (num_vertices,3,D), count > D, values not finite or
// beyond kMaxDmplDisplacement (validate_inputs.h). Other keys are ignored.
Result<DmplBasis> loadDmplBasis(const std::string& path, int num_vertices, int count = 0);

// `--dmpl DIR`: the basis for a motion's gender, looked up as AMASS lays it
// out: <DIR>/dmpls/<gender>/model.npz, else <DIR>/<gender>/model.npz (so DIR
// may be the --model folder or its dmpls/ folder). `gender` as the motion
// stores it; unknown or absent -> neutral. When the wanted gender is missing,
// neutral is used and `note` says so. Errors name DIR and what was tried.
Result<std::string> findDmplBasis(const std::string& dir, const std::string& gender,
                                  std::string* note);

}  // namespace smpl
