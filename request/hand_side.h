// A MANO motion's hand side against the MANO model's (docs/motions.md "Decoder spec: HaMeR hands").
// A hand motion (Motion::hand, e.g. HaMeR's is_right) holds its side's own pose; the model's side
// comes from its file name (core/math/mirror_model.h manoSide: MANO_LEFT.pkl). When the two differ,
// the export poses the model mirrored by S = diag(-1,1,1) (mirrorModel: x negated, triangle winding
// flipped), so a left hand on MANO_RIGHT is exactly HaMeR's mirrored mesh: mirrored(S R S) = S
// MANO_RIGHT(R). The mirrored model belongs to the one export (the cached model is never changed)
// and its arrays are charged to the memory budget.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/memory_budget.h"
#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

struct HandSideModel {
  std::unique_ptr<BodyModel> mirrored;  // null: the model's side fits (or no hand motion)
  MemoryCharge charge;                  // the mirrored model's arrays
};

// For a MANO `model` and motions whose first has a hand side different from
// the model's: the mirrored model, and on each hand motion the note "track 1 is a
// left hand on a right MANO model: exported as the mirrored model (x negated,
// triangle winding flipped), as HaMeR shows it; give MANO_LEFT to pose a left
// hand". Errors (naming `paths[i]`): motions of both sides in one export, the
// memory budget.
Result<HandSideModel> modelForHandSide(const BodyModel& model,
                                       const std::vector<std::string>& paths,
                                       std::vector<Motion>* motions);

}  // namespace smpl
