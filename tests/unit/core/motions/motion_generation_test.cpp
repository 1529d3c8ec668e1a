// The motion-generation, hand and position layouts (docs/motions.md
// "Motion-generation tools, hand and camera-frame fits"): Motion-X column
// blocks (core/motions/motion_motionx.h), MDM's 6D rows and root translation
// (motion_mdm.h), the joint-position refusals (motion_positions.h), HaMeR's
// sides, rows and tracks (motion_hamer.h), and where each sits in the reader
// table. Trees are built in code, so every value is known; the end-to-end
// numbers (three.js against numpy) are tests/cli/layouts/generation_cases.py.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/math/forward.h"
#include "core/math/mirror_model.h"
#include "core/motions/motion.h"
#include "core/motions/motion_hamer.h"
#include "core/motions/motion_layout.h"
#include "core/motions/motion_mdm.h"
#include "core/motions/motion_motionx.h"
#include "core/motions/motion_positions.h"
#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::numbers;

using test::leaf;

DataNode dict(std::vector<std::pair<std::string, DataNode>> items) {
  DataNode d;
  d.kind = DataNode::Kind::Dict;
  for (auto& [key, child] : items) {
    d.keys.push_back(key);
    d.children.push_back(std::move(child));
  }
  return d;
}

// Member names only, as a row's `matches` sees an .npz.
DataNode names(std::initializer_list<const char*> keys) {
  DataNode d;
  d.kind = DataNode::Kind::Dict;
  for (const char* k : keys) d.keys.push_back(k);
  d.children.resize(d.keys.size());
  return d;
}

Result<MotionSet> decode(const MotionLayout& row, const DataNode& root, bool frame_file = false) {
  MotionOptions options;
  options.frame_file = frame_file;
  MotionSet set;
  if (Status st = row.decode(root, LayoutInput{"x.npy", options}, &set); !st) return st.error();
  return set;
}

Eigen::Matrix3d rodrigues(double x, double y, double z) {
  return rotationsFromAxisAngle(Eigen::Vector3d(x, y, z))[0];
}

bool hasNote(const Motion& m, const std::string& text) {
  for (const std::string& n : m.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

// ---- Motion-X ---------------------------------------------------------------------------------

// (T,width) with column c of frame f = 0.001 (c + 1) (1 + f): every column tells where it went.
Array motionxArray(int64_t t, int64_t width) {
  Array a = numbers({t, width}, {});
  for (int64_t f = 0; f < t; ++f)
    for (int64_t c = 0; c < width; ++c) a.data.push_back(0.001 * (c + 1) * (1 + f));
  return a;
}

Eigen::Matrix3d motionxJoint(int64_t f, int64_t first_column) {
  const double s = 0.001 * (1 + f);
  return rodrigues(s * (first_column + 1), s * (first_column + 2), s * (first_column + 3));
}

TEST(MotionX, ColumnBlocksOf322) {
  Result<MotionSet> set = decode(motionxLayout(), leaf(motionxArray(2, 322)));
  ASSERT_TRUE(set.ok()) << set.message();
  ASSERT_EQ(set->tracks.size(), 1u);
  const Motion& m = set->tracks[0];
  EXPECT_EQ(m.layout, ModelKind::SmplX);
  ASSERT_EQ(m.frames.size(), 2u);
  for (int64_t f = 0; f < 2; ++f) {
    const Rotations& r = m.frames[f];
    EXPECT_TRUE(r[0].isApprox(motionxJoint(f, 0), 1e-12));     // root 0:3
    EXPECT_TRUE(r[21].isApprox(motionxJoint(f, 63), 1e-12));   // body joint 21 at 63:66
    EXPECT_TRUE(r[25].isApprox(motionxJoint(f, 66), 1e-12));   // left hand first: 66:111
    EXPECT_TRUE(r[40].isApprox(motionxJoint(f, 111), 1e-12));  // right hand: 111:156
    EXPECT_TRUE(r[22].isApprox(motionxJoint(f, 156), 1e-12));  // jaw 156:159
    EXPECT_TRUE(r[23].isIdentity(0) && r[24].isIdentity(0));   // eyes at rest
    const double s = 0.001 * (1 + f);
    EXPECT_NEAR(m.translation[f].x(), s * 310, 1e-12);  // trans 309:312
    ASSERT_EQ(m.expression.rows(), 2);
    ASSERT_EQ(m.expression.cols(), 50);  // face_expr 159:209
    EXPECT_NEAR(m.expression(f, 0), s * 160, 1e-12);
    EXPECT_NEAR(m.expression(f, 49), s * 209, 1e-12);
  }
  ASSERT_EQ(m.betas.size(), 10u);  // 312:322, rows differ: their mean
  EXPECT_NEAR(m.betas[0], 0.0015 * 313, 1e-12);
  EXPECT_TRUE(m.hands.left.empty() && m.hands.right.empty());  // absolute: nothing added later
  EXPECT_EQ(m.world, MotionWorld::Y);
  EXPECT_EQ(m.fps, 0.0);  // loadMotionSet settles the row's 30 fps with the documented-rate note
  EXPECT_TRUE(hasNote(m, "face_shape (100 FLAME shape coefficients")) << m.notes.size();
  EXPECT_TRUE(hasNote(m, "per-frame rows differ"));
  EXPECT_EQ(motionxLayout().fps_fallback, 30.0);
}

TEST(MotionX, The172LayoutHasNoFace) {
  Result<MotionSet> set = decode(motionxLayout(), leaf(motionxArray(3, 172)));
  ASSERT_TRUE(set.ok()) << set.message();
  const Motion& m = set->tracks[0];
  EXPECT_EQ(m.expression.rows(), 0);
  EXPECT_NEAR(m.translation[2].z(), 0.003 * 162, 1e-12);  // trans 159:162
  EXPECT_NEAR(m.betas[9], 0.002 * 172, 1e-12);            // betas 162:172, mean of 1x, 2x, 3x
  EXPECT_FALSE(hasNote(m, "face_shape"));
}

TEST(MotionX, BadValuesAreRefused) {
  Array empty = numbers({0, 322}, {});
  Result<MotionSet> none = decode(motionxLayout(), leaf(empty));
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.message().find("has shape (0,322); expected (T,322) with T >= 1"),
            std::string::npos)
      << none.message();
  Array nan = motionxArray(2, 172);
  nan.data[5] = std::nan("");
  Result<MotionSet> bad = decode(motionxLayout(), leaf(nan));
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("NaN"), std::string::npos) << bad.message();
}

// ---- Detection --------------------------------------------------------------------------------

TEST(GenerationLayouts, DetectionByShapeAndKeys) {
  auto found = [](const DataNode& root, unsigned container) {
    const MotionLayout* row = findLayout(root, container);
    return std::string(row ? row->name : "none");
  };
  EXPECT_EQ(found(leaf(numbers({4, 322}, std::vector<double>(4 * 322))), kNpyFile), "motionx");
  EXPECT_EQ(found(leaf(numbers({4, 172}, std::vector<double>(4 * 172))), kNpyFile), "motionx");
  EXPECT_EQ(found(leaf(numbers({4, 165}, std::vector<double>(4 * 165))), kNpyFile), "bare_poses");
  EXPECT_EQ(found(leaf(numbers({4, 99}, std::vector<double>(4 * 99))), kNpyFile), "none");
  EXPECT_EQ(found(leaf(numbers({4, 22, 3}, std::vector<double>(4 * 66))), kNpyFile), "positions");
  EXPECT_EQ(found(leaf(numbers({4, 21, 3}, std::vector<double>(4 * 63))), kNpyFile), "positions");
  EXPECT_EQ(found(leaf(numbers({4, 263}, std::vector<double>(4 * 263))), kNpyFile), "positions");
  EXPECT_EQ(found(leaf(numbers({4, 251}, std::vector<double>(4 * 251))), kNpyFile), "positions");
  // MDM: smpl_params (motion + thetas) vs results.npy (motion + lengths).
  EXPECT_EQ(
      found(names({"motion", "thetas", "root_translation", "faces", "vertices", "text", "length"}),
            kNpyFile),
      "mdm");
  EXPECT_EQ(found(names({"motion", "text", "lengths", "num_samples", "num_repetitions"}), kNpyFile),
            "positions");
  // HaMeR has the fit's global_orient but no body_pose: never read as a fit, and a fit never
  // as HaMeR.
  EXPECT_EQ(found(names({"global_orient", "hand_pose", "betas", "is_right"}), kNpzFile), "hamer");
  EXPECT_EQ(found(names({"pred_mano_params", "pred_cam_t_full", "right"}), kNpzFile), "hamer");
  EXPECT_EQ(
      found(names({"pred_mano_params.global_orient", "pred_mano_params.hand_pose"}), kNpzFile),
      "hamer");
  EXPECT_EQ(found(names({"global_orient", "body_pose", "hand_pose"}), kPickleFile), "fit");
  EXPECT_EQ(found(names({"global_orient", "body_pose", "left_hand_pose"}), kNpzFile), "fit");
}

TEST(GenerationLayouts, PositionsAreRefusedWithWhatToDo) {
  const std::string fit = "joint positions, no rotations: fit a body first, e.g. with SMPLify";
  Result<MotionSet> joints =
      decode(positionsLayout(), leaf(numbers({2, 22, 3}, std::vector<double>(132))));
  ASSERT_FALSE(joints.ok());
  EXPECT_EQ(joints.message(),
            "x.npy: " + fit + " (MDM: visualize/render_mesh.py writes *_smpl_params.npy)");
  Result<MotionSet> features =
      decode(positionsLayout(), leaf(numbers({2, 263}, std::vector<double>(526))));
  ASSERT_FALSE(features.ok());
  EXPECT_EQ(features.message(), "x.npy: HumanML3D motion features: " + fit);
  Result<MotionSet> results = decode(
      positionsLayout(), dict({{"motion", leaf(numbers({1, 22, 3, 2}, std::vector<double>(132)))},
                               {"lengths", leaf(numbers({1}, {2}))}}));
  ASSERT_FALSE(results.ok());
  EXPECT_NE(results.message().find(fit), std::string::npos);
}

// ---- MDM --------------------------------------------------------------------------------------

TEST(Mdm, SixDIsTheFirstTwoRows) {
  const Eigen::Matrix3d r = rodrigues(0.3, -0.5, 0.8);
  ASSERT_FALSE(r.isApprox(r.transpose(), 1e-3));  // rows and columns readings differ
  double a[6] = {r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2)};
  Result<Eigen::Matrix3d> got = rotationFrom6d(a, "frame 0 joint 0");
  ASSERT_TRUE(got.ok()) << got.message();
  EXPECT_TRUE(got->isApprox(r, 1e-12)) << *got;
  // A network's raw 6D: scaled, the second vector not orthogonal: Gram-Schmidt gives R again.
  double raw[6];
  for (int c = 0; c < 3; ++c) {
    raw[c] = 1.3 * a[c];
    raw[3 + c] = 0.8 * a[3 + c] + 0.4 * a[c];
  }
  Result<Eigen::Matrix3d> again = rotationFrom6d(raw, "frame 0 joint 0");
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_TRUE(again->isApprox(r, 1e-12)) << *again;
}

TEST(Mdm, DegenerateSixDNamesFrameAndJoint) {
  double zero[6] = {0, 0, 0, 0, 1, 0};
  Result<Eigen::Matrix3d> a = rotationFrom6d(zero, "frame 3 joint 5");
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.message(), "the 6D rotation of frame 3 joint 5 has a zero first vector");
  double parallel[6] = {1, 2, 3, 2, 4, 6};
  Result<Eigen::Matrix3d> b = rotationFrom6d(parallel, "frame 0 joint 1");
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.message().find("zero or parallel to the first"), std::string::npos);
}

// An MDM dict with T frames: joint j at frame f rotated by rodrigues(0.1 j, 0.05 f, -0.02 j);
// the root position (1 + f, 0.9, -f).
DataNode mdmTree(int64_t t, bool packed) {
  Array six = numbers({packed ? 25 : 24, 6, t}, std::vector<double>((packed ? 25 : 24) * 6 * t));
  Array root = numbers({3, t}, std::vector<double>(3 * t));
  for (int64_t f = 0; f < t; ++f) {
    for (int64_t j = 0; j < 24; ++j) {
      const Eigen::Matrix3d r = rodrigues(0.1 * j, 0.05 * f, -0.02 * j);
      for (int c = 0; c < 6; ++c) six.data[(j * 6 + c) * t + f] = r(c / 3, c % 3);
    }
    const double p[3] = {1.0 + f, 0.9, -1.0 * f};
    for (int c = 0; c < 3; ++c)
      (packed ? six.data[(24 * 6 + c) * t + f] : root.data[c * t + f]) = p[c];
  }
  if (packed) return dict({{"motion", leaf(six)}, {"text", leaf(Array())}});
  return dict({{"thetas", leaf(six)}, {"root_translation", leaf(root)}});
}

TEST(Mdm, RotationsAndTranslationRelativeToFrameZero) {
  for (bool packed : {true, false}) {
    SCOPED_TRACE(packed ? "motion (25,6,T)" : "thetas + root_translation");
    Result<MotionSet> set = decode(mdmLayout(), mdmTree(3, packed));
    ASSERT_TRUE(set.ok()) << set.message();
    const Motion& m = set->tracks[0];
    EXPECT_EQ(m.layout, ModelKind::Smpl);
    ASSERT_EQ(m.frames.size(), 3u);
    EXPECT_TRUE(m.frames[2][7].isApprox(rodrigues(0.7, 0.1, -0.14), 1e-12));
    EXPECT_TRUE(m.translation[0].isZero(0));
    EXPECT_TRUE(m.translation[2].isApprox(Eigen::Vector3d(2, 0, -2), 1e-12)) << m.translation[2];
    EXPECT_TRUE(m.betas.empty());
    EXPECT_EQ(m.world, MotionWorld::Y);
  }
  EXPECT_EQ(mdmLayout().fps_fallback, 20.0);
}

TEST(Mdm, ShapesAreChecked) {
  Result<MotionSet> bad =
      decode(mdmLayout(), dict({{"motion", leaf(numbers({24, 6, 2}, std::vector<double>(288)))},
                                {"thetas", leaf(numbers({24, 6, 2}, std::vector<double>(288)))}}));
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("'motion' has shape (24,6,2); expected (25,6,T)"), std::string::npos)
      << bad.message();
  DataNode zeros = mdmTree(2, true);
  std::fill(zeros.children[0].array.data.begin(), zeros.children[0].array.data.end(), 0.0);
  Result<MotionSet> degenerate = decode(mdmLayout(), zeros);
  ASSERT_FALSE(degenerate.ok());
  EXPECT_EQ(degenerate.message(),
            "x.npy: the 6D rotation of frame 0 joint 0 has a zero first vector");
}

// ---- HaMeR ------------------------------------------------------------------------------------

// Rows of HaMeR hands: row i rotated by rodrigues(0.2 + 0.1 i, -0.3, 0.05 j) at joint j.
Eigen::Matrix3d hamerJoint(int64_t i, int64_t j) {
  return rodrigues(0.2 + 0.1 * i, -0.3, 0.05 * j);
}

DataNode hamerTree(const std::vector<double>& sides, bool nested, const char* trans_key) {
  const int64_t n = static_cast<int64_t>(sides.size());
  Array orient = numbers({n, 1, 3, 3}, {}), pose = numbers({n, 15, 3, 3}, {});
  Array betas = numbers({n, 10}, {}), cam = numbers({n, 3}, {});
  for (int64_t i = 0; i < n; ++i) {
    for (int64_t j = 0; j < 16; ++j) {
      const Eigen::Matrix3d r = hamerJoint(i, j);
      for (int c = 0; c < 9; ++c) (j == 0 ? orient : pose).data.push_back(r(c / 3, c % 3));
    }
    for (int c = 0; c < 10; ++c) betas.data.push_back(0.1 * i + 0.01 * c);
    for (int c = 0; c < 3; ++c) cam.data.push_back(0.1 * (i + 1) + c);
  }
  std::vector<std::pair<std::string, DataNode>> params = {
      {"global_orient", leaf(orient)}, {"hand_pose", leaf(pose)}, {"betas", leaf(betas)}};
  std::vector<std::pair<std::string, DataNode>> top;
  if (nested)
    top.push_back({"pred_mano_params", dict(std::move(params))});
  else
    top = std::move(params);
  top.push_back({"is_right", leaf(numbers({n}, sides))});
  if (trans_key) top.push_back({trans_key, leaf(cam)});
  return dict(std::move(top));
}

TEST(Hamer, OneRightHandThroughTime) {
  Result<MotionSet> set = decode(hamerLayout(), hamerTree({1, 1, 1}, false, "pred_cam_t_full"));
  ASSERT_TRUE(set.ok()) << set.message();
  ASSERT_EQ(set->tracks.size(), 1u);
  const Motion& m = set->tracks[0];
  EXPECT_EQ(m.layout, ModelKind::Mano);
  EXPECT_EQ(m.hand, "right");
  EXPECT_EQ(m.track, "");
  EXPECT_EQ(m.world, MotionWorld::CameraYDown);
  ASSERT_EQ(m.frames.size(), 3u);
  EXPECT_TRUE(m.frames[2][0].isApprox(hamerJoint(2, 0), 1e-12));
  EXPECT_TRUE(m.frames[1][15].isApprox(hamerJoint(1, 15), 1e-12));
  EXPECT_TRUE(m.translation[2].isApprox(Eigen::Vector3d(0.3, 1.3, 2.3), 1e-12));
  EXPECT_NEAR(m.betas[0], 0.1, 1e-12);  // rows differ: their mean
  EXPECT_TRUE(hasNote(m, "read as HaMeR output"));
  EXPECT_TRUE(hasNote(m, "per-frame rows differ"));
}

// A left hand is posed as the left hand's own pose, S R S: MANO_LEFT(S R S) = S MANO_RIGHT(R).
TEST(Hamer, LeftHandIsTheMirroredPose) {
  Result<MotionSet> set = decode(hamerLayout(), hamerTree({0, 0}, true, "pred_cam_t_full"));
  ASSERT_TRUE(set.ok()) << set.message();
  const Motion& m = set->tracks[0];
  EXPECT_EQ(m.hand, "left");
  for (int64_t j : {0, 7, 15}) {
    const Eigen::Matrix3d r = hamerJoint(1, j);
    EXPECT_TRUE(m.frames[1][j].isApprox(mirrorRotation(r), 1e-12)) << j;
    EXPECT_FALSE(m.frames[1][j].isApprox(r, 1e-6)) << j;
  }
  EXPECT_TRUE(m.translation[0].isApprox(Eigen::Vector3d(0.1, 1.1, 2.1), 1e-12));  // not mirrored
}

TEST(Hamer, MixedSidesInOneFileAreRefused) {
  Result<MotionSet> set = decode(hamerLayout(), hamerTree({0, 1}, false, "pred_cam_t_full"));
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.message(),
            "x.npy: 'is_right' mixes left and right hands in one file without a frame index: save "
            "one hand per file, or one file per frame for --motion-sequence");
}

// One frame of a --motion-sequence: rows are hands, the k-th of a side is track 2k + is_right.
TEST(Hamer, FrameFileRowsAreTracks) {
  Result<MotionSet> set =
      decode(hamerLayout(), hamerTree({0, 1, 0, 1, 1}, true, "pred_cam_t_full"), true);
  ASSERT_TRUE(set.ok()) << set.message();
  ASSERT_EQ(set->tracks.size(), 5u);
  const char* ids[] = {"0", "1", "2", "3", "5"};
  for (size_t i = 0; i < 5; ++i) {
    const Motion& m = set->tracks[i];
    EXPECT_EQ(m.track, ids[i]) << i;
    EXPECT_EQ(m.hand, i == 0 || i == 2 ? "left" : "right") << i;
    ASSERT_EQ(m.frames.size(), 1u);
    const Eigen::Matrix3d r = hamerJoint(static_cast<int64_t>(i), 3);
    EXPECT_TRUE(m.frames[0][3].isApprox(m.hand == "left" ? mirrorRotation(r) : r, 1e-12)) << i;
    EXPECT_NEAR(m.betas[0], 0.1 * i, 1e-12) << i;
    EXPECT_TRUE(hasNote(m, "HaMeR does not track hands")) << i;
  }
  Result<MotionSet> two = decode(hamerLayout(), hamerTree({0, 1}, true, "pred_cam_t_full"), true);
  ASSERT_TRUE(two.ok()) << two.message();
  EXPECT_FALSE(hasNote(two->tracks[0], "HaMeR does not track hands"));  // one hand per side
}

TEST(Hamer, TranslationSources) {
  Result<MotionSet> crop = decode(hamerLayout(), hamerTree({1}, false, "pred_cam_t"));
  ASSERT_TRUE(crop.ok()) << crop.message();
  EXPECT_TRUE(hasNote(crop->tracks[0], "pred_cam_t is the crop camera's translation"));
  EXPECT_TRUE(crop->tracks[0].translation[0].isApprox(Eigen::Vector3d(0.1, 1.1, 2.1), 1e-12));
  Result<MotionSet> none = decode(hamerLayout(), hamerTree({1}, false, nullptr));
  ASSERT_TRUE(none.ok()) << none.message();
  EXPECT_TRUE(hasNote(none->tracks[0], "the translation is zero"));
  EXPECT_TRUE(none->tracks[0].translation[0].isZero(0));
}

TEST(Hamer, FlattenedNamesAndShapeErrors) {
  DataNode flat = hamerTree({1, 1}, false, "pred_cam_t_full");
  for (size_t i = 0; i < 3; ++i) flat.keys[i] = "pred_mano_params." + flat.keys[i];
  Result<MotionSet> set = decode(hamerLayout(), flat);
  ASSERT_TRUE(set.ok()) << set.message();
  EXPECT_TRUE(set->tracks[0].frames[1][0].isApprox(hamerJoint(1, 0), 1e-12));
  DataNode aa = hamerTree({1, 1}, false, "pred_cam_t_full");
  aa.children[1].array.shape = {2, 45, 3};
  Result<MotionSet> bad = decode(hamerLayout(), aa);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.message(),
            "x.npy: 'hand_pose' has shape (2,45,3); expected (N,15,3,3) rotation matrices");
  DataNode short_side = hamerTree({1, 1}, false, "pred_cam_t_full");
  short_side.children[3].array = numbers({1}, {1});
  Result<MotionSet> side = decode(hamerLayout(), short_side);
  ASSERT_FALSE(side.ok());
  EXPECT_EQ(side.message(), "x.npy: 'is_right' has shape (1,); expected (2,)");
}

// ---- Through loadMotion (the fixtures of make_generation_layouts.py) -------------------------

const std::string kGeneration = std::string(SMPL_FIXTURE_DIR) + "/layouts/generation/";

// The documented rates settle with their notes; MDM's pickled torch tensor (`vertices`, not
// read) does not fail the file.
TEST(GenerationLayouts, FilesLoadWithTheirDocumentedRates) {
  struct Case {
    const char* file;
    const char* layout;
    size_t frames;
    double fps;
    const char* note;
  } cases[] = {
      {"motionx/smplx322_walk.npy", "motionx", 24, 30,
       "Motion-X stores no frame rate; its documentation gives 30 fps; assumed 30 fps"},
      {"mdm/sample00_rep00_smpl_params.npy", "mdm", 30, 20,
       "MDM (HumanML3D) stores no frame rate; its documentation gives 20 fps; assumed 20 fps"},
      {"hamer/left_hand.npz", "hamer", 20, 30, "no frame rate is stored; assumed 30 fps"},
  };
  for (const Case& c : cases) {
    Result<Motion> m = loadMotion(kGeneration + c.file);
    ASSERT_TRUE(m.ok()) << m.message();
    EXPECT_EQ(m->source_layout, c.layout);
    EXPECT_EQ(m->frames.size(), c.frames) << c.file;
    EXPECT_EQ(m->fps, c.fps) << c.file;
    EXPECT_TRUE(m->fps_assumed) << c.file;
    EXPECT_TRUE(hasNote(*m, c.note)) << c.file;
  }
  Result<Motion> hand = loadMotion(kGeneration + "hamer/left_hand.npz");
  ASSERT_TRUE(hand.ok());
  EXPECT_EQ(hand->hand, "left");
  EXPECT_TRUE(hasNote(*hand, "HaMeR's pred_cam_t_full places the hand in the camera"));
  for (const char* file : {"humanml3d/new_joints_000021.npy", "mdm/results.npy"}) {
    Result<Motion> refused = loadMotion(kGeneration + file);
    ASSERT_FALSE(refused.ok()) << file;
    EXPECT_EQ(refused.message(),
              kGeneration + file +
                  ": joint positions, no rotations: fit a body first, e.g. with SMPLify (MDM: "
                  "visualize/render_mesh.py writes *_smpl_params.npy)");
  }
}

}  // namespace
}  // namespace smpl
