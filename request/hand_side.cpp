#include "request/hand_side.h"

#include "core/io/printable.h"
#include "core/math/mirror_model.h"
#include "request/model_source.h"

namespace smpl {

Result<HandSideModel> modelForHandSide(const BodyModel& model,
                                       const std::vector<std::string>& paths,
                                       std::vector<Motion>* motions) {
  HandSideModel out;
  if (motions->empty() || model.kind != ModelKind::Mano || motions->front().hand.empty())
    return out;
  const std::string hand = motions->front().hand, side = manoSide(model);
  for (size_t i = 1; i < motions->size(); ++i)
    if (!(*motions)[i].hand.empty() && (*motions)[i].hand != hand)
      return makeError(paths[i] + ": a " + (*motions)[i].hand + " hand in an export whose first " +
                       "motion is a " + hand + " hand: export each side on its own");
  if (hand == side) return out;
  if (Status st = out.charge.add(modelBytes(model), model.name, "the mirrored model"); !st)
    return st.error();
  out.mirrored = std::make_unique<BodyModel>(mirrorModel(model));
  const std::string model_file = hand == "left" ? "MANO_LEFT" : "MANO_RIGHT";
  for (Motion& m : *motions) {
    if (m.hand.empty()) continue;
    const std::string who = m.track.empty() ? "" : "track " + printable(m.track, 64) + " is ";
    m.notes.push_back(who + "a " + hand + " hand on a " + side +
                      " MANO model: exported as the mirrored model (x negated, triangle winding "
                      "flipped), as HaMeR shows it; give " +
                      model_file + " to pose a " + hand + " hand");
  }
  return out;
}

}  // namespace smpl
