// A hand motion's side against the MANO model's (request/hand_side.h):
// a left hand on MANO_RIGHT (and a right hand on MANO_LEFT) poses the model
// mirrored by S = diag(-1,1,1), owned by the export; the same side, a body
// model or a motion without a side use the model as it is.
#include "request/hand_side.h"

#include <gtest/gtest.h>

#include "core/models/model_loader.h"

namespace smpl {
namespace {

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

Motion hand(const char* side, const char* track = "") {
  Motion m;
  m.layout = ModelKind::Mano;
  m.hand = side;
  m.track = track;
  return m;
}

TEST(HandSide, OtherSideGetsTheMirroredModel) {
  Result<BodyModel> right = loadModel(kModels + "mano_small.npz");
  ASSERT_TRUE(right.ok()) << right.message();
  std::vector<Motion> motions = {hand("left", "2")};
  Result<HandSideModel> side = modelForHandSide(*right, {"hands/"}, &motions);
  ASSERT_TRUE(side.ok()) << side.message();
  ASSERT_TRUE(side->mirrored);
  const BodyModel& m = *side->mirrored;
  EXPECT_TRUE(m.v_template.col(0).isApprox(-right->v_template.col(0), 0));
  EXPECT_TRUE(m.v_template.col(1).isApprox(right->v_template.col(1), 0));
  EXPECT_EQ(m.faces(0, 1), right->faces(0, 2));  // winding flipped
  EXPECT_EQ(m.faces(0, 2), right->faces(0, 1));
  EXPECT_GT(side->charge.bytes(), 0u);  // the job-owned copy is on the memory budget
  ASSERT_EQ(motions[0].notes.size(), 1u);
  EXPECT_EQ(motions[0].notes[0],
            "track 2 is a left hand on a right MANO model: exported as the mirrored model (x "
            "negated, triangle winding flipped), as HaMeR shows it; give MANO_LEFT to pose a left "
            "hand");
}

TEST(HandSide, SameSideBodyModelsAndSidelessMotionsKeepTheModel) {
  Result<BodyModel> right = loadModel(kModels + "mano_small.npz");
  Result<BodyModel> left = loadModel(kModels + "mano_left_small.npz");
  Result<BodyModel> body = loadModel(kModels + "smplh_small.npz");
  ASSERT_TRUE(right.ok() && left.ok() && body.ok());
  struct Case {
    const BodyModel* model;
    const char* side;
    bool mirrored;
  } cases[] = {{&*right, "right", false},
               {&*left, "left", false},
               {&*left, "right", true},
               {&*right, "", false},
               {&*body, "left", false}};
  for (const Case& c : cases) {
    std::vector<Motion> motions = {hand(c.side)};
    Result<HandSideModel> side = modelForHandSide(*c.model, {"m.npz"}, &motions);
    ASSERT_TRUE(side.ok()) << side.message();
    EXPECT_EQ(static_cast<bool>(side->mirrored), c.mirrored) << c.model->name << " " << c.side;
    EXPECT_EQ(motions[0].notes.size(), c.mirrored ? 1u : 0u);
    if (c.mirrored)
      EXPECT_EQ(motions[0].notes[0].rfind("a right hand on a left MANO model: ", 0), 0u)
          << motions[0].notes[0];
  }
}

TEST(HandSide, BothSidesInOneExportAreRefused) {
  Result<BodyModel> right = loadModel(kModels + "mano_small.npz");
  ASSERT_TRUE(right.ok());
  std::vector<Motion> motions = {hand("right"), hand("left")};
  Result<HandSideModel> side = modelForHandSide(*right, {"a.npz", "b.npz"}, &motions);
  ASSERT_FALSE(side.ok());
  EXPECT_EQ(side.message(),
            "b.npz: a left hand in an export whose first motion is a right hand: export each "
            "side on its own");
}

}  // namespace
}  // namespace smpl
