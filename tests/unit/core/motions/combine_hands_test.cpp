// Hand tracks into a body clip (core/motions/combine_hands.h): fingers by
// joint name on SMPL-H as on SMPL-X, the wrist as Mano2Smpl-X sets it, frame
// matching by index and by frame number, and the one-line refusals. The
// SMPL-X path is checked end to end against numpy by the hands_* layout
// cases (tests/cli/layouts/video_cases.py).
#include "core/motions/combine_hands.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace smpl {
namespace {

Eigen::Matrix3d turn(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A body clip of `t` frames: every joint a different turn, camera frame.
Motion body(ModelKind layout, int joints, int t) {
  Motion m;
  m.layout = layout;
  m.world = MotionWorld::CameraYDown;
  for (int f = 0; f < t; ++f) {
    Rotations r(joints);
    for (int j = 0; j < joints; ++j) r[j] = turn(0.1 + 0.01 * j + 0.05 * f, {1.0, 0.3 * j, -0.2});
    m.frames.push_back(r);
  }
  return m;
}

// A hand track of `t` frames: joint k of frame f turned 0.2 + 0.03 k + 0.1 f about (k, 1, f).
Motion hand(const std::string& side, int t) {
  Motion m;
  m.layout = ModelKind::Mano;
  m.hand = side;
  m.world = MotionWorld::CameraYDown;
  for (int f = 0; f < t; ++f) {
    Rotations r(16);
    for (int k = 0; k < 16; ++k) r[k] = turn(0.2 + 0.03 * k + 0.1 * f, {1.0 * k, 1.0, 1.0 * f});
    m.frames.push_back(r);
  }
  return m;
}

bool hasNote(const Motion& m, const std::string& text) {
  for (const std::string& n : m.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

TEST(CombineHands, FingersOfSmplhByNameTheWristStaysTheBodys) {
  Motion b = body(ModelKind::SmplH, 52, 3);
  const Motion before = b;
  Motion right = hand("right", 3);
  ASSERT_TRUE(combineHands({HandTrack{&right, "r.npz"}}, false, "walk.npz", &b).ok());
  for (int f = 0; f < 3; ++f) {
    for (int k = 0; k < 15; ++k)  // SMPL-H: right_index1 is joint 37
      EXPECT_TRUE(b.frames[f][37 + k].isApprox(right.frames[f][1 + k], 1e-15)) << f << " " << k;
    for (int j = 0; j < 37; ++j) EXPECT_EQ(b.frames[f][j], before.frames[f][j]) << j;
  }
  EXPECT_TRUE(hasNote(b, "r.npz: the right hand's fingers (absolute MANO rotations"));
}

TEST(CombineHands, WristGivesTheHandsGlobalOrientation) {
  Motion b = body(ModelKind::SmplX, 55, 2);
  Motion left = hand("left", 2);
  ASSERT_TRUE(combineHands({HandTrack{&left, "l.npz"}}, true, "g.pt", &b).ok());
  for (int f = 0; f < 2; ++f) {
    const Rotations& r = b.frames[f];
    // pelvis, spine1, spine2, spine3, left_collar, left_shoulder, left_elbow, left_wrist
    const Eigen::Matrix3d wrist = r[0] * r[3] * r[6] * r[9] * r[13] * r[16] * r[18] * r[20];
    EXPECT_TRUE(wrist.isApprox(left.frames[f][0], 1e-12)) << f;
    EXPECT_TRUE(r[25].isApprox(left.frames[f][1], 1e-15));  // left_index1
  }
  EXPECT_TRUE(hasNote(b, "the left hand's wrist and fingers"));
}

TEST(CombineHands, FrameNumbersAndMissingFrames) {
  Motion b = body(ModelKind::SmplX, 55, 6);
  b.first_frame = 10;
  const Motion before = b;
  Motion right = hand("right", 3);  // source frames 12-14, 13 held
  right.track = "1";
  right.first_frame = 12;
  right.held = {false, true, false};
  ASSERT_TRUE(combineHands({HandTrack{&right, "hamer"}}, false, "g.pt", &b).ok());
  EXPECT_TRUE(b.frames[2][40].isApprox(right.frames[0][1], 1e-15));  // frame 12
  EXPECT_EQ(b.frames[3][40], before.frames[3][40]);                  // 13: held, the body's
  EXPECT_TRUE(b.frames[4][40].isApprox(right.frames[2][1], 1e-15));  // frame 14
  EXPECT_TRUE(hasNote(b, "hamer: track 1: the right hand's fingers"));
  EXPECT_TRUE(
      hasNote(b, "4 of 6 frames have no frame of this track and keep the body clip's hand"));
}

TEST(CombineHands, RefusalsNameTheFile) {
  Motion left = hand("left", 4), left2 = hand("left", 4), shortr = hand("right", 3);
  Motion sided = hand("", 4), late = hand("right", 4), camera = hand("right", 4);
  late.track = "1", late.first_frame = 2;
  struct Case {
    Motion body;
    std::vector<HandTrack> hands;
    bool wrist;
    std::string message;
  };
  Motion world = body(ModelKind::SmplX, 55, 4);
  world.world = MotionWorld::Y;
  const Case cases[] = {
      {body(ModelKind::Smpl, 24, 4),
       {{&left, "l.npz"}},
       false,
       "b.pkl: --hands drives the fingers of an SMPL-X or SMPL-H body clip; this clip is smpl (no "
       "finger joints)"},
      {body(ModelKind::SmplX, 55, 4),
       {{&left, "l.npz"}, {&left2, "h"}},
       false,
       "h: a second left hand (the first: l.npz): give one hand track per side"},
      {body(ModelKind::SmplX, 55, 4),
       {{&shortr, "r.npz"}},
       false,
       "r.npz: 3 hand frames for the body clip's 4 (b.pkl): a hand track without frame numbers "
       "is matched by index and must have the body clip's length"},
      {body(ModelKind::SmplX, 55, 4),
       {{&sided, "x.npz"}},
       false,
       "x.npz: a MANO track without a side (no is_right): --hands cannot tell which hand it "
       "drives"},
      {body(ModelKind::SmplX, 55, 4),
       {{&world, "g.pt"}},
       false,
       "g.pt: not a hand track (a smplx motion): --hands takes MANO hand tracks (HaMeR, WiLoR)"},
      {body(ModelKind::SmplX, 55, 4),
       {{&late, "h"}},
       false,
       "h: track 1: source frames 2-5 are not all in the body clip's 0-3 (b.pkl): frames are "
       "matched by number"},
      {world,
       {{&camera, "r.npz"}},
       true,
       "b.pkl: --hands-wrist needs the body clip in the camera frame of the hand track (give "
       "--source-params incam for the body's camera-frame parameters)"},
  };
  for (const Case& c : cases) {
    Motion b = c.body;
    const Motion before = b;
    Status st = combineHands(c.hands, c.wrist, "b.pkl", &b);
    ASSERT_FALSE(st.ok()) << c.message;
    EXPECT_EQ(st.message(), c.message);
    EXPECT_EQ(b.frames, before.frames) << c.message;  // nothing changed on a refusal
  }
}

}  // namespace
}  // namespace smpl
