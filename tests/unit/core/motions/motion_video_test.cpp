// The video-to-motion layouts (docs/motions.md "Video-to-motion layouts"):
// detection by content against the other rows, shape errors, refusals and
// the conventions the case runner (tests/cli/layouts/video_cases.py) does not
// pin: detections vs held entries (PHALP), frame numbers of one file vs a
// sequence (EasyMocap, SMPLer-X), GVHMR's pending mean hands, BEV's anchor
// and infant tracks. Fixtures: tests/fixtures/make_video_layouts.py; small
// trees are built here.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <utility>

#include "core/io/tree/data_tree.h"
#include "core/models/model_loader.h"
#include "core/motions/motion.h"
#include "core/motions/motion_amass.h"
#include "core/motions/motion_easymocap.h"
#include "core/motions/motion_fit.h"
#include "core/motions/motion_gvhmr.h"
#include "core/motions/motion_layout.h"
#include "core/motions/motion_phalp.h"
#include "core/motions/motion_read.h"
#include "core/motions/motion_romp.h"
#include "core/motions/motion_sequence.h"
#include "core/motions/motion_tram.h"
#include "core/motions/motion_vibe.h"
#include "core/motions/motion_wham.h"

namespace smpl {
namespace {

const std::string kVideo = std::string(SMPL_FIXTURE_DIR) + "/layouts/video/";

DataNode leaf(std::vector<int64_t> shape, std::vector<double> data) {
  DataNode n;
  n.kind = DataNode::Kind::Array;
  n.array.shape = std::move(shape);
  n.array.data = std::move(data);
  n.array.dtype = "<f8";
  return n;
}

DataNode zeros(std::vector<int64_t> shape) {
  int64_t n = 1;
  for (int64_t d : shape) n *= d;
  return leaf(std::move(shape), std::vector<double>(n, 0.0));
}

DataNode dict(std::vector<std::pair<std::string, DataNode>> items) {
  DataNode n;
  n.kind = DataNode::Kind::Dict;
  for (auto& [k, v] : items) {
    n.keys.push_back(k);
    n.children.push_back(std::move(v));
  }
  return n;
}

DataNode list(std::vector<DataNode> items) {
  DataNode n;
  n.kind = DataNode::Kind::List;
  n.children = std::move(items);
  return n;
}

LayoutInput input(const std::string& path, SourceParams params = SourceParams::Default) {
  LayoutInput in{path, MotionOptions()};
  in.options.source_params = params;
  return in;
}

bool hasNote(const std::vector<std::string>& notes, const std::string& text) {
  for (const std::string& n : notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

// A WHAM track of `t` frames starting at `first`: pose root (0, 0.2, 0),
// pose_world root (0.1, 0, 0), trans (1, 2, 3), trans_world (4, 5, 6).
DataNode whamTrack(int64_t t, int64_t first) {
  std::vector<double> pose(72 * t, 0.0), world(72 * t, 0.0), trans, trans_world, ids;
  for (int64_t f = 0; f < t; ++f) {
    pose[72 * f + 1] = 0.2;
    world[72 * f] = 0.1;
    trans.insert(trans.end(), {1, 2, 3});
    trans_world.insert(trans_world.end(), {4, 5, 6});
    ids.push_back(static_cast<double>(first + f));
  }
  return dict({{"pose", leaf({t, 72}, pose)},
               {"trans", leaf({t, 3}, trans)},
               {"pose_world", leaf({t, 72}, world)},
               {"trans_world", leaf({t, 3}, trans_world)},
               {"betas", zeros({t, 10})},
               {"frame_ids", leaf({t}, ids)}});
}

TEST(VideoLayouts, FixturesAreReadByTheirRowsOnly) {
  const std::pair<const char*, const char*> files[] = {{"wham/wham_output.pkl", "wham"},
                                                       {"vibe/vibe_output.pkl", "vibe"},
                                                       {"phalp/demo_video.pkl", "phalp"},
                                                       {"gvhmr/hmr4d_results.pt", "gvhmr"},
                                                       {"gvhmr/hmr4d_results.pkl", "gvhmr"},
                                                       {"gvhmr/gvhmr_flat.npz", "fit"},
                                                       {"romp/video_results.npz", "romp"},
                                                       {"bev/video_results.npz", "romp"},
                                                       {"easymocap/smpl/000007.json", "easymocap"},
                                                       {"smplerx/smplx/00003_0.npz", "smplerx"},
                                                       {"tram/seq/hps/hps_track_0.npy", "tram"},
                                                       {"tram_cam/hps_track_0.npy", "tram"}};
  for (const auto& [file, row] : files) {
    Result<MotionFile> f = readMotionFile(kVideo + file);
    ASSERT_TRUE(f.ok()) << f.message();
    ASSERT_NE(f->layout, nullptr) << file;
    EXPECT_STREQ(f->layout->name, row) << file;
    if (std::string(row) == "fit" || std::string(row) == "smplerx") continue;  // fit keys
    // The flat rows never take a tool's nested file (a WHAM file is not AMASS's).
    EXPECT_FALSE(amassLayout().matches(f->root)) << file;
    EXPECT_FALSE(fitLayout().matches(f->root)) << file;
  }
  // WHAM's tracks have 'trans'; VIBE's do not: each row refuses the other's tree.
  Result<MotionFile> wham = readMotionFile(kVideo + "wham/wham_output.pkl");
  Result<MotionFile> vibe = readMotionFile(kVideo + "vibe/vibe_output.pkl");
  ASSERT_TRUE(wham.ok() && vibe.ok());
  EXPECT_FALSE(vibeLayout().matches(wham->root));
  EXPECT_FALSE(whamLayout().matches(vibe->root));
}

TEST(VideoLayouts, WhamReadsWorldOrCameraParameters) {
  const DataNode root = dict({{"3", whamTrack(4, 10)}, {"7", whamTrack(2, 0)}});
  MotionSet world;
  ASSERT_TRUE(whamLayout().decode(root, input("w.pkl"), &world).ok());
  ASSERT_EQ(world.tracks.size(), 2u);
  const Motion& m = world.tracks[0];
  EXPECT_EQ(m.track, "3");
  EXPECT_EQ(m.first_frame, 10);
  EXPECT_EQ(m.world, MotionWorld::Y);
  EXPECT_TRUE(m.frames[0][0].isApprox(
      Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()).toRotationMatrix(), 1e-12));
  EXPECT_EQ(m.translation[3], Eigen::Vector3d(4, 5, 6));
  MotionSet cam;
  ASSERT_TRUE(whamLayout().decode(root, input("w.pkl", SourceParams::Incam), &cam).ok());
  EXPECT_EQ(cam.tracks[0].world, MotionWorld::CameraYDown);
  EXPECT_TRUE(cam.tracks[0].frames[0][0].isApprox(
      Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix(), 1e-12));
  EXPECT_EQ(cam.tracks[0].translation[0], Eigen::Vector3d(1, 2, 3));
  // Without pose_world: the camera parameters with a note, or an error if asked for.
  DataNode only_cam = whamTrack(2, 0);
  only_cam.keys[2] = "x";
  MotionSet fallback;
  ASSERT_TRUE(whamLayout().decode(dict({{"0", only_cam}}), input("w.pkl"), &fallback).ok());
  EXPECT_EQ(fallback.tracks[0].world, MotionWorld::CameraYDown);
  Status global =
      whamLayout().decode(dict({{"0", only_cam}}), input("w.pkl", SourceParams::Global), &fallback);
  ASSERT_FALSE(global.ok());
  EXPECT_NE(global.message().find("--source-params global"), std::string::npos);
}

TEST(VideoLayouts, WhamShapeErrorsNameTrackAndKey) {
  struct Bad {
    const char* key;
    DataNode value;
    const char* message;
  } cases[] = {
      {"betas", zeros({2, 10}),
       "w.pkl: track 3: 'betas' has shape (2,10); expected (3,B) like the poses"},
      {"pose_world", zeros({3, 70}), "w.pkl: track 3: 'pose_world' has shape (3,70); expected"},
      {"trans_world", zeros({2, 3}),
       "w.pkl: track 3: 'trans_world' has shape (2,3); expected (3,3)"},
      {"frame_ids", zeros({4}), "w.pkl: track 3: 'frame_ids' has shape (4,); expected (3,)"},
      {"frame_ids", leaf({3}, {0, 1, -2}), "'frame_ids' element 2 is -2"},
      {"pose_world", leaf({1, 72}, std::vector<double>(72, NAN)), "'pose_world' contains NaN"},
  };
  for (Bad& b : cases) {
    DataNode track = whamTrack(3, 0);
    for (size_t i = 0; i < track.keys.size(); ++i)
      if (track.keys[i] == b.key) track.children[i] = b.value;
    MotionSet set;
    Status st = whamLayout().decode(dict({{"3", track}}), input("w.pkl"), &set);
    ASSERT_FALSE(st.ok()) << b.message;
    EXPECT_NE(st.message().find(b.message), std::string::npos) << st.message();
  }
}

TEST(VideoLayouts, LayoutsWithoutWorldOrCameraParametersRefuseThem) {
  const struct {
    std::string file;
    SourceParams params;
    const char* message;
  } cases[] = {
      {"vibe/vibe_output.pkl", SourceParams::Global, "VIBE output has no world-frame parameters"},
      {"phalp/demo_video.pkl", SourceParams::Global, "PHALP output has no world-frame parameters"},
      {"romp/video_results.npz", SourceParams::Global, "output has no world-frame parameters"},
      {"easymocap/smpl/000003.json", SourceParams::Incam,
       "EasyMocap output has no camera-frame parameters"},
  };
  for (const auto& c : cases) {
    MotionOptions o;
    o.source_params = c.params;
    Result<MotionSet> set = loadMotionSet(kVideo + c.file, o);
    ASSERT_FALSE(set.ok()) << c.file;
    EXPECT_NE(set.message().find(c.message), std::string::npos) << set.message();
    o.source_params = SourceParams::Default;
    EXPECT_TRUE(loadMotionSet(kVideo + c.file, o).ok()) << c.file;
  }
}

// A PHALP frame: `tid` entries with their tracked_time and camera x.
DataNode phalpFrame(int64_t time, std::vector<double> tid, std::vector<double> since,
                    std::vector<double> camera_x) {
  std::vector<DataNode> smpl, camera;
  for (size_t i = 0; i < tid.size(); ++i) {
    smpl.push_back(dict({{"global_orient", leaf({1, 3, 3}, {1, 0, 0, 0, 1, 0, 0, 0, 1})},
                         {"body_pose", zeros({23, 3, 3})},
                         {"betas", zeros({10})}}));
    for (int j = 0; j < 23; ++j)  // identity matrices
      for (int d = 0; d < 3; ++d) smpl.back().children[1].array.data[9 * j + 4 * d] = 1;
    camera.push_back(leaf({3}, {camera_x[i], 0, 5}));
  }
  return dict({{"time", leaf({}, {static_cast<double>(time)})},
               {"tid", leaf({static_cast<int64_t>(tid.size())}, tid)},
               {"tracked_time", leaf({static_cast<int64_t>(since.size())}, since)},
               {"smpl", list(smpl)},
               {"camera", list(camera)}});
}

TEST(VideoLayouts, PhalpRowsAreDetectionsOnly) {
  // Track 5: detected at frames 0 and 2; at frame 1 PHALP lists it with
  // tracked_time 1 and a stale entry (camera x 9) that must not become a row.
  const DataNode root = dict({{"a.jpg", phalpFrame(0, {5}, {0}, {1})},
                              {"b.jpg", phalpFrame(1, {5}, {1}, {9})},
                              {"c.jpg", phalpFrame(2, {5}, {0}, {3})}});
  ASSERT_TRUE(phalpLayout().matches(root));
  MotionSet set;
  ASSERT_TRUE(phalpLayout().decode(root, input("p.pkl"), &set).ok());
  ASSERT_EQ(set.tracks.size(), 1u);
  const Motion& m = set.tracks[0];
  EXPECT_EQ(m.track, "5");
  ASSERT_EQ(m.frames.size(), 3u);
  EXPECT_EQ(m.held_frames, 1);
  EXPECT_EQ(m.translation[1].x(), 1.0);  // holds frame 0's detection, not the stale entry
  EXPECT_EQ(m.translation[2].x(), 3.0);
  // No frame detects anyone: refused.
  const DataNode none = dict({{"a.jpg", phalpFrame(0, {5}, {2}, {1})}});
  Status st = phalpLayout().decode(none, input("p.pkl"), &set);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("p.pkl: no tracked person"), std::string::npos) << st.message();
}

TEST(VideoLayouts, GvhmrHandsWaitForTheModelsMean) {
  Result<MotionSet> set = loadMotionSet(kVideo + "gvhmr/hmr4d_results.pt");
  ASSERT_TRUE(set.ok()) << set.message();
  Motion m = set->tracks[0];
  EXPECT_EQ(m.layout, ModelKind::SmplX);
  ASSERT_EQ(m.hands.left.size(), m.frames.size());
  EXPECT_EQ(m.hands.right[5], Eigen::VectorXd::Zero(45));
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smplx_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  Motion with_mean = m;
  ASSERT_TRUE(resolveFitHands(*model, false, "g.pt", &with_mean).ok());
  const Rotations mean = rotationsFromAxisAngle(model->hands_mean_l);
  EXPECT_TRUE(with_mean.frames[3][25].isApprox(mean[0], 1e-12));
  // A model without hands_mean: the hands stay at rest, with a note (not an error).
  BodyModel bare = *model;
  bare.hands_mean_l.resize(0);
  bare.hands_mean_r.resize(0);
  ASSERT_TRUE(resolveFitHands(bare, false, "g.pt", &m).ok());
  EXPECT_TRUE(m.frames[3][25].isIdentity(1e-12));
  EXPECT_TRUE(hasNote(m.notes, "no hands_mean"));
  // Shapes are named by their key path.
  DataNode root = dict({{"smpl_params_global", dict({{"body_pose", zeros({4, 63})},
                                                     {"global_orient", zeros({4, 3})},
                                                     {"transl", zeros({3, 3})}})}});
  MotionSet bad;
  Status st = gvhmrLayout().decode(root, input("g.pt"), &bad);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("g.pt: 'smpl_params_global/transl' has shape (3,3); expected (4,3)"),
            std::string::npos)
      << st.message();
  st = gvhmrLayout().decode(root, input("g.pt", SourceParams::Incam), &bad);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("no 'smpl_params_incam'"), std::string::npos) << st.message();
}

// ROMP's sequence_results entry for one track (betas of `width` columns, age `age`).
DataNode rompTrack(int64_t n, int64_t width, double age) {
  std::vector<double> betas(n * width, 0.1), ids;
  for (int64_t f = 0; f < n; ++f) {
    if (width == 11) betas[f * 11 + 10] = age;
    ids.push_back(static_cast<double>(f));
  }
  return dict({{"frame_id", leaf({n}, ids)},
               {"smpl_thetas", zeros({n, 72})},
               {"smpl_betas", leaf({n, width}, betas)},
               {"cam_trans", zeros({n, 3})}});
}

TEST(VideoLayouts, BevAnchorsAtTheHipsAndLeavesInfantsOut) {
  Result<MotionSet> bev = loadMotionSet(kVideo + "bev/video_results.npz");
  ASSERT_TRUE(bev.ok()) << bev.message();
  const Motion& m = bev->tracks[0];
  EXPECT_EQ(m.source_layout, "bev");
  EXPECT_EQ(m.betas.size(), 10u);
  EXPECT_EQ(m.translation_anchor, (std::vector<std::string>{"left_hip", "right_hip"}));
  Result<MotionSet> romp = loadMotionSet(kVideo + "romp/video_results.npz");
  ASSERT_TRUE(romp.ok()) << romp.message();
  EXPECT_EQ(romp->tracks[0].source_layout, "romp");
  EXPECT_TRUE(romp->tracks[0].translation_anchor.empty());
  // An infant track among adults is left out with a note; infants only: refused.
  const DataNode mixed = dict(
      {{"results", dict({})},
       {"sequence_results", dict({{"1", rompTrack(3, 11, 0.9)}, {"2", rompTrack(4, 11, 0.2)}})}});
  MotionSet set;
  ASSERT_TRUE(rompLayout().decode(mixed, input("v.npz"), &set).ok());
  ASSERT_EQ(set.tracks.size(), 1u);
  EXPECT_EQ(set.tracks[0].track, "2");
  EXPECT_TRUE(hasNote(set.notes, "track(s) 1: BEV's infant body (SMIL, age coefficient 0.9"));
  const DataNode infant =
      dict({{"results", dict({})}, {"sequence_results", dict({{"1", rompTrack(3, 11, 0.85)}})}});
  MotionSet none;
  Status st = rompLayout().decode(infant, input("v.npz"), &none);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("v.npz: BEV's infant body (SMIL, age coefficient 0.85 > 0.8) is "
                              "not an SMPL body"),
            std::string::npos)
      << st.message();
}

TEST(VideoLayouts, EasymocapFramesComeFromTheNameOrTheSequence) {
  Result<MotionSet> one = loadMotionSet(kVideo + "easymocap/smpl/000007.json");
  ASSERT_TRUE(one.ok()) << one.message();
  ASSERT_EQ(one->tracks.size(), 2u);
  for (const Motion& m : one->tracks) {
    EXPECT_EQ(m.first_frame, 7) << m.track;
    EXPECT_EQ(m.world, MotionWorld::Z);
    ASSERT_EQ(m.world_rotation.size(), 1u);
    EXPECT_TRUE(m.frames[0][0].isIdentity(1e-12));  // poses[:3] is written as zero
    EXPECT_EQ(m.translation[0], Eigen::Vector3d::Zero());
  }
  Result<MotionSet> seq = loadMotionSequence(kVideo + "easymocap/smpl");
  ASSERT_TRUE(seq.ok()) << seq.message();
  ASSERT_EQ(seq->tracks.size(), 2u);
  EXPECT_EQ(seq->tracks[0].first_frame, 0);
  EXPECT_EQ(seq->tracks[1].first_frame, 4);
  EXPECT_EQ(seq->tracks[1].frames.size(), 10u);
  EXPECT_TRUE(hasNote(seq->notes, "read as EasyMocap output"));
  // The frame change of frame 7 of person 1 is that file's Rh/Th.
  EXPECT_TRUE(seq->tracks[1].world_rotation[3].isApprox(one->tracks[1].world_rotation[0], 1e-12));
  EXPECT_EQ(seq->tracks[1].world_translation[3], one->tracks[1].world_translation[0]);
  Result<MotionSet> smplx = loadMotionSet(kVideo + "easymocap_smplx/000000.json");
  ASSERT_FALSE(smplx.ok());
  EXPECT_NE(smplx.message().find("EasyMocap SMPL-H/SMPL-X parameters ('handl', 'handr', "
                                 "'expression') are not read"),
            std::string::npos)
      << smplx.message();
  const DataNode person = dict({{"id", leaf({}, {2})},
                                {"Rh", zeros({1, 3})},
                                {"Th", zeros({1, 3})},
                                {"poses", zeros({1, 72})}});
  MotionSet twice;
  Status st = easymocapLayout().decode(list({person, person}), input("000001.json"), &twice);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("two persons with id 2"), std::string::npos) << st.message();
}

TEST(VideoLayouts, SmplerxConventionsOnlyInASequence) {
  Result<Motion> one = loadMotion(kVideo + "smplerx/smplx/00003_0.npz");
  ASSERT_TRUE(one.ok()) << one.message();
  EXPECT_EQ(one->source_layout, "fit");
  EXPECT_EQ(one->world, MotionWorld::Y);
  EXPECT_FALSE(hasNote(one->notes, "SMPLer-X"));
  Result<MotionSet> seq = loadMotionSequence(kVideo + "smplerx/smplx");
  ASSERT_TRUE(seq.ok()) << seq.message();
  const Motion& m = seq->tracks[0];
  EXPECT_EQ(m.source_layout, "smplerx");
  EXPECT_EQ(m.world, MotionWorld::CameraYDown);
  EXPECT_TRUE(hasNote(seq->notes, "read as SMPLer-X output"));
  // Every clip frame has its pending hands, a held frame holding the previous ones.
  ASSERT_EQ(m.hands.left.size(), m.frames.size());
  EXPECT_EQ(m.held_frames, 1);
  EXPECT_EQ(m.hands.left[11 - 3], m.hands.left[10 - 3]);  // frame 11 has no detection
  EXPECT_NE(m.hands.left[12 - 3], m.hands.left[10 - 3]);
  MotionOptions global;
  global.source_params = SourceParams::Global;
  Result<MotionSet> refused = loadMotionSequence(kVideo + "smplerx/smplx", global);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("SMPLer-X output has no world-frame parameters"),
            std::string::npos)
      << refused.message();
}

// A TRAM track of `t` identity poses at frames first.. (tensors read as Arrays).
DataNode tramTrack(int64_t t, int64_t first) {
  std::vector<double> rot(216 * t, 0.0), frames;
  for (int64_t i = 0; i < 24 * t; ++i)
    for (int d = 0; d < 3; ++d) rot[9 * i + 4 * d] = 1;
  for (int64_t f = 0; f < t; ++f) frames.push_back(static_cast<double>(first + f));
  return dict({{"pred_rotmat", leaf({t, 24, 3, 3}, rot)},
               {"pred_trans", zeros({t, 1, 3})},
               {"pred_shape", zeros({t, 10})},
               {"frame", leaf({t}, frames)}});
}

TEST(VideoLayouts, TramPlacesTheCameraFromCameraNpy) {
  // The fixture's camera.npy (30 cameras) sits at <track dir>/../camera.npy.
  const std::string track = kVideo + "tram/seq/hps/hps_track_9.npy";
  MotionSet world;
  ASSERT_TRUE(tramLayout().decode(tramTrack(3, 4), input(track), &world).ok());
  const Motion& m = world.tracks[0];
  EXPECT_EQ(m.world, MotionWorld::Y);
  EXPECT_EQ(m.first_frame, 4);
  EXPECT_EQ(m.track, "");
  ASSERT_EQ(m.world_rotation.size(), 3u);
  Result<DataNode> cam = readDataTree(kVideo + "tram/seq/camera.npy");
  ASSERT_TRUE(cam.ok()) << cam.message();
  const Array* t = cam->leaf("world_cam_T");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(m.world_translation[1], Eigen::Vector3d(t->data[15], t->data[16], t->data[17]));
  const Array* r = cam->leaf("world_cam_R");  // row 1 is frame 5
  ASSERT_NE(r, nullptr);
  const Eigen::Matrix3d r5 =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r->data.data() + 45);
  EXPECT_TRUE(m.world_rotation[1].isApprox(r5, 1e-6));  // re-orthonormalised float32
  MotionSet cam_frame;
  ASSERT_TRUE(
      tramLayout().decode(tramTrack(3, 4), input(track, SourceParams::Incam), &cam_frame).ok());
  EXPECT_EQ(cam_frame.tracks[0].world, MotionWorld::CameraYDown);
  EXPECT_TRUE(cam_frame.tracks[0].world_rotation.empty());
  MotionSet bad;
  Status st = tramLayout().decode(tramTrack(3, 28), input(track), &bad);  // frames 28-30 of 30
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("frame 30 is beyond the 30 cameras of"), std::string::npos)
      << st.message();
  const std::string alone = kVideo + "tram_cam/hps_track_0.npy";  // no camera.npy beside
  st = tramLayout().decode(tramTrack(2, 0), input(alone, SourceParams::Global), &bad);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("--source-params global: no camera.npy beside the track"),
            std::string::npos)
      << st.message();
  MotionSet none;
  ASSERT_TRUE(tramLayout().decode(tramTrack(2, 0), input(alone), &none).ok());
  EXPECT_EQ(none.tracks[0].world, MotionWorld::CameraYDown);
  EXPECT_NE(none.tracks[0].world_why.find("no camera.npy beside the track"), std::string::npos);
}

}  // namespace
}  // namespace smpl
