// People and frames (core/motions/motion_tracks.h, motion_sequence.h): track
// choice, held frames, the longest track and its notes, per-frame folders.
#include "core/motions/motion_tracks.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/motions/motion_sequence.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {

const std::string kVideo = std::string(SMPL_FIXTURE_DIR) + "/layouts/video/";

// A track of `n` SMPL frames whose root rotation about x encodes the row (0.1 * row).
Motion track(const std::string& id, int n) {
  Motion m;
  m.track = id;
  for (int r = 0; r < n; ++r) {
    Rotations frame(24, Eigen::Matrix3d::Identity());
    frame[0] = Eigen::AngleAxisd(0.1 * r, Eigen::Vector3d::UnitX()).toRotationMatrix();
    m.frames.push_back(frame);
    m.translation.emplace_back(r, 0, 0);
  }
  return m;
}

bool hasNote(const Motion& m, const std::string& text) {
  for (const std::string& n : m.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

TEST(MotionTracks, ChoiceParses) {
  EXPECT_EQ(parseTrackChoice("longest")->kind, TrackChoice::Kind::Longest);
  EXPECT_EQ(parseTrackChoice("all")->kind, TrackChoice::Kind::All);
  EXPECT_EQ(parseTrackChoice("12")->id, "12");
  for (const char* bad : {"", "a b", "x/y", "../1"}) {
    Result<TrackChoice> c = parseTrackChoice(bad);
    ASSERT_FALSE(c.ok()) << bad;
    EXPECT_EQ(c.kind(), ErrorKind::Usage);
  }
}

TEST(MotionTracks, IdsOfAnyLengthOrderAsNumbersAndRepeatsAreRefused) {
  MotionSet set;
  for (const char* id : {"18446744073709551616", "9007199254740993", "-3", "9007199254740992"})
    set.tracks.push_back(track(id, 2));
  Result<std::vector<Motion>> all = selectTracks(set, *parseTrackChoice("all"), "w.pkl");
  ASSERT_TRUE(all.ok()) << all.message();
  std::vector<std::string> order;
  for (const Motion& m : *all) order.push_back(m.track);
  EXPECT_EQ(order, (std::vector<std::string>{"-3", "9007199254740992", "9007199254740993",
                                             "18446744073709551616"}));
  Result<std::vector<Motion>> pick =
      selectTracks(set, *parseTrackChoice("9007199254740993"), "w.pkl");
  ASSERT_TRUE(pick.ok()) << pick.message();
  EXPECT_EQ(pick->front().track, "9007199254740993");
  set.tracks.push_back(track("-3", 2));
  Result<std::vector<Motion>> twice = selectTracks(set, *parseTrackChoice("all"), "w.pkl");
  ASSERT_FALSE(twice.ok());
  EXPECT_EQ(twice.message(), "w.pkl: two tracks have the id -3; give them distinct ids");
}

TEST(MotionTracks, RowsAreOrderedAndGapsHoldThePreviousDetection) {
  Motion m = track("4", 3);  // rows 0, 1, 2 detected at frames 8, 3, 5
  ASSERT_TRUE(assembleTrack({8, 3, 5}, "f.pkl", &m).ok());
  EXPECT_EQ(m.first_frame, 3);
  ASSERT_EQ(m.frames.size(), 6u);  // 3..8
  EXPECT_EQ(m.held_frames, 3);
  const int rows[] = {1, 1, 2, 2, 2, 0};  // frame 3 -> row 1, 4 holds it, 5 -> row 2, ...
  for (int f = 0; f < 6; ++f) EXPECT_EQ(m.translation[f].x(), rows[f]) << f;
  const std::vector<bool> held = {false, true, false, true, true, false};  // no detection
  EXPECT_EQ(m.held, held);
  EXPECT_TRUE(
      hasNote(m, "track 4: source frames without a detection: 3 (each holds the previous one)"));
  Motion whole = track("2", 2);
  ASSERT_TRUE(assembleTrack({4, 5}, "f.pkl", &whole).ok());
  EXPECT_TRUE(whole.held.empty());  // every frame a detection
  Motion twice = track("1", 2);
  Status st = assembleTrack({7, 7}, "f.pkl", &twice);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("f.pkl: track 1 has two poses for frame 7"), std::string::npos);
}

TEST(MotionTracks, LongestTiesToTheLowerIdAndNotesTheOthers) {
  MotionSet set;
  set.tracks = {track("10", 5), track("2", 5), track("3", 2)};
  set.tracks[2].first_frame = 40;
  Result<std::vector<Motion>> picked = selectTracks(set, TrackChoice(), "w.pkl");
  ASSERT_TRUE(picked.ok()) << picked.message();
  ASSERT_EQ(picked->size(), 1u);
  EXPECT_EQ(picked->front().track, "2");  // 2 < 10 as numbers
  EXPECT_TRUE(hasNote(picked->front(),
                      "track 2 of 3 (source frames 0-4, the longest); other tracks: "
                      "3 (40-41), 10 (0-4); pick one with --track ID or all"))
      << picked->front().notes[0];
  Result<std::vector<Motion>> all =
      selectTracks(set, TrackChoice{TrackChoice::Kind::All, ""}, "w.pkl");
  ASSERT_TRUE(all.ok());
  ASSERT_EQ(all->size(), 3u);
  EXPECT_EQ((*all)[2].track, "10");
  Result<std::vector<Motion>> none = selectTracks(set, *parseTrackChoice("7"), "w.pkl");
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.message(), "w.pkl: no track 7 (tracks: 2, 3, 10)");
  MotionSet one;
  one.tracks = {track("", 3)};
  Result<std::vector<Motion>> id = selectTracks(one, *parseTrackChoice("0"), "g.pt");
  ASSERT_FALSE(id.ok());
  EXPECT_EQ(id.message(), "g.pt: no track 0 (one person, no track ids)");
  EXPECT_TRUE(selectTracks(one, TrackChoice(), "g.pt")->front().notes.empty());
}

TEST(MotionSequence, FrameNames) {
  int64_t frame = 0;
  std::string person;
  EXPECT_TRUE(parseFrameName("00012_0.npz", &frame, &person));
  EXPECT_EQ(frame, 12);
  EXPECT_EQ(person, "0");
  EXPECT_TRUE(parseFrameName("000012.json", &frame, &person));
  EXPECT_EQ(person, "");
  for (const char* bad :
       {"walk.npz", "12_a.npz", "12.txt", "12.glb.smpl.json", "_1.npz", "0000000000012.npz"})
    EXPECT_FALSE(parseFrameName(bad, &frame, &person)) << bad;
}

// SMPLer-X writes one fit per detection and frame (00012_0.npz: frame 12,
// person 0); the folder joins into one track per person, in frame order.
TEST(MotionSequence, PerFrameFilesJoinPerPerson) {
  const std::string dir = kVideo + "smplerx/smplx";
  Result<MotionSet> set = loadMotionSequence(dir);
  ASSERT_TRUE(set.ok()) << set.message();
  ASSERT_EQ(set->tracks.size(), 2u);
  const Motion& p0 = set->tracks[0];
  EXPECT_EQ(p0.track, "0");
  EXPECT_EQ(p0.first_frame, 3);
  EXPECT_EQ(p0.name, "smplx");
  for (int64_t f : {3, 9, 20}) {
    char name[32];
    std::snprintf(name, sizeof name, "/%05lld_0.npz", static_cast<long long>(f));
    Result<Motion> one = loadMotion(dir + name);
    ASSERT_TRUE(one.ok()) << one.message();
    EXPECT_LT((p0.frames[f - 3][5] - one->frames[0][5]).cwiseAbs().maxCoeff(), 1e-12) << f;
    EXPECT_LT((p0.translation[f - 3] - one->translation[0]).norm(), 1e-12) << f;
  }
  EXPECT_NE(set->notes[0].find("30 files joined (frames 3-"), std::string::npos) << set->notes[0];
}

// Ids read from arrays (PHALP 'tid', EasyMocap 'id') arrive as doubles: ids
// up to 9e15 are exact decimal text; 2^53 + 1 and above cannot be told from a
// neighbour, so they are refused with a message that says why, never rounded.
TEST(TrackIds, ArrayIdsAreExactOrRefusedNeverRounded) {
  Result<std::string> small = video_rows::idText(12345678901234.0, "f.pkl", "tid");
  ASSERT_TRUE(small.ok()) << small.message();
  EXPECT_EQ(*small, "12345678901234");
  Result<std::string> edge = video_rows::idText(8999999999999998.0, "f.pkl", "tid");
  ASSERT_TRUE(edge.ok()) << edge.message();
  EXPECT_EQ(*edge, "8999999999999998");
  for (double big : {9007199254740993.0, 1e16, 9.2233720368547758e18}) {
    Result<std::string> r = video_rows::idText(big, "f.pkl", "tid");
    ASSERT_FALSE(r.ok()) << *r;
    EXPECT_NE(r.message().find("f.pkl: 'tid' holds an id of about "), std::string::npos)
        << r.message();
    EXPECT_NE(r.message().find("beyond the largest"), std::string::npos) << r.message();
  }
  for (double bad : {-1.0, 2.5}) {
    Result<std::string> r = video_rows::idText(bad, "f.pkl", "tid");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.message().find("is not a non-negative integer id"), std::string::npos);
  }
}

}  // namespace
}  // namespace smpl
