// PromptHMR results.pkl, its world4d.mcs scene and Multi-HMR per-image files
// (docs/motions.md "PromptHMR", "Multi-HMR"): the scene camera each reader
// fills (MotionSet::camera, scene_camera.h) against the fixture's own numbers
// (tests/fixtures/make_video_layouts.py writes expected/prompthmr_camera.json
// from Rwc / Twc, the reader takes Rcw / Tcw or the .mcs quaternions), the
// tracks' timeline, and the joint mapping the case runner cannot see.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "core/io/base64.h"
#include "core/io/tree/data_tree.h"
#include "core/motions/motion.h"
#include "core/motions/motion_sequence.h"

namespace smpl {
namespace {

const std::string kVideo = std::string(SMPL_FIXTURE_DIR) + "/layouts/video/";

struct ExpectedCamera {
  std::vector<Eigen::Matrix3d> rotation;
  std::vector<Eigen::Vector3d> position;
  double yfov = 0, aspect = 0;
};

ExpectedCamera expectedCamera() {
  Result<DataNode> tree = readDataTree(kVideo + "expected/prompthmr_camera.json");
  EXPECT_TRUE(tree) << (tree ? "" : tree.error().message);
  ExpectedCamera e;
  const Array* r = tree->leaf("rotation");
  const Array* p = tree->leaf("position");
  for (int64_t f = 0; f < r->shape[0]; ++f) {
    e.rotation.push_back(
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r->data.data() + 9 * f));
    e.position.push_back(Eigen::Map<const Eigen::Vector3d>(p->data.data() + 3 * f));
  }
  e.yfov = tree->leaf("yfov")->data[0];
  e.aspect = tree->leaf("aspect")->data[0];
  return e;
}

void expectCamera(const SceneCamera& c, const ExpectedCamera& e, double tol) {
  ASSERT_EQ(c.rotation.size(), e.rotation.size());
  ASSERT_EQ(c.position.size(), e.position.size());
  EXPECT_EQ(c.first_frame, 0);
  for (size_t f = 0; f < e.rotation.size(); ++f) {
    EXPECT_LT((c.rotation[f] - e.rotation[f]).cwiseAbs().maxCoeff(), tol) << "frame " << f;
    EXPECT_LT((c.position[f] - e.position[f]).norm(), tol) << "frame " << f;
  }
  EXPECT_NEAR(c.yfov, e.yfov, 1e-6);
  EXPECT_NEAR(c.aspect, e.aspect, 1e-6);
}

TEST(PromptHmr, CameraWorldIsCameraToWorldAndCentre) {
  Result<MotionSet> set = loadMotionSet(kVideo + "prompthmr/results.pkl");
  ASSERT_TRUE(set) << set.error().message;
  expectCamera(set->camera, expectedCamera(), 2e-6);
}

TEST(PromptHmr, IncamCameraIsTheCameraFrame) {
  MotionOptions o;
  o.source_params = SourceParams::Incam;
  Result<MotionSet> set = loadMotionSet(kVideo + "prompthmr/results.pkl", o);
  ASSERT_TRUE(set) << set.error().message;
  ASSERT_EQ(set->camera.rotation.size(), 30u);
  EXPECT_TRUE(set->camera.rotation[7].isIdentity());
  EXPECT_TRUE(set->camera.position[7].isZero());
}

TEST(PromptHmr, TracksKeepTheirStartFramesAndLengths) {
  Result<MotionSet> set = loadMotionSet(kVideo + "prompthmr/results.pkl");
  ASSERT_TRUE(set) << set.error().message;
  ASSERT_EQ(set->tracks.size(), 2u);
  EXPECT_EQ(set->tracks[0].track, "1");
  EXPECT_EQ(set->tracks[0].first_frame, 0);
  EXPECT_EQ(set->tracks[0].frames.size(), 20u);
  EXPECT_EQ(set->tracks[1].track, "2");
  EXPECT_EQ(set->tracks[1].first_frame, 6);
  EXPECT_EQ(set->tracks[1].frames.size(), 24u);
}

TEST(Mcs, BodiesOnTheSceneTimelineAndTheCameraAnimation) {
  for (const char* name : {"prompthmr/world4d.mcs", "prompthmr/world4d.glb"}) {
    Result<MotionSet> set = loadMotionSet(kVideo + name);
    ASSERT_TRUE(set) << set.error().message;
    ASSERT_EQ(set->tracks.size(), 2u) << name;
    EXPECT_EQ(set->tracks[0].track, "0");
    EXPECT_EQ(set->tracks[1].track, "1");
    EXPECT_EQ(set->tracks[0].first_frame, 0);
    EXPECT_EQ(set->tracks[1].first_frame, 6);
    EXPECT_EQ(set->tracks[1].frames.size(), 24u);
    EXPECT_DOUBLE_EQ(set->tracks[1].fps, 25.0);
    EXPECT_EQ(set->tracks[0].source_layout, "mcs");
    expectCamera(set->camera, expectedCamera(), 2e-6);  // float32 quaternions and positions
  }
}

TEST(MultiHmr, RotvecJointsByNameAndThePelvisAnchor) {
  Result<MotionSet> set = loadMotionSet(kVideo + "multihmr/000003.npz");
  ASSERT_TRUE(set) << set.error().message;
  ASSERT_EQ(set->tracks.size(), 2u);
  const Motion& m = set->tracks[1];
  EXPECT_EQ(m.track, "1");
  EXPECT_EQ(m.translation_anchor, std::vector<std::string>{"pelvis"});
  EXPECT_EQ(m.world, MotionWorld::CameraYDown);
  Result<DataNode> raw = readDataTree(kVideo + "multihmr/000003.npz");
  ASSERT_TRUE(raw);
  const Array* rotvec = raw->leaf("rotvec");
  auto rotation = [&](int k) {  // rotvec joint k of person 1
    const Eigen::Vector3d v = Eigen::Map<const Eigen::Vector3d>(rotvec->data.data() + 159 + 3 * k);
    return Eigen::AngleAxisd(v.norm(), v.normalized()).toRotationMatrix();
  };
  // SMPL-X joints: 22 jaw <- rotvec 52; 25 left_index1 <- 22; 40 right_index1 <- 37; 23, 24 eyes at
  // rest.
  for (auto [smplx, k] :
       std::vector<std::pair<int, int>>{{0, 0}, {21, 21}, {22, 52}, {25, 22}, {40, 37}, {54, 51}})
    EXPECT_LT((m.frames[0][smplx] - rotation(k)).cwiseAbs().maxCoeff(), 1e-6) << smplx;
  EXPECT_TRUE(m.frames[0][23].isIdentity());
  EXPECT_TRUE(m.frames[0][24].isIdentity());
}

TEST(Base64, DecodesAndRefusesTruncatedOrForeignText) {
  Result<std::vector<uint8_t>> ok = decodeBase64("aGk/Pz4+", "t");
  ASSERT_TRUE(ok);
  EXPECT_EQ(std::string(ok->begin(), ok->end()), "hi??>>");
  Result<std::vector<uint8_t>> padded = decodeBase64("aGk=", "t");
  ASSERT_TRUE(padded);
  EXPECT_EQ(std::string(padded->begin(), padded->end()), "hi");
  EXPECT_EQ(base64DecodedSize("aGk="), 2u);
  Result<std::vector<uint8_t>> truncated = decodeBase64("aGk", "t");
  ASSERT_FALSE(truncated);
  EXPECT_NE(truncated.error().message.find("truncated"), std::string::npos);
  EXPECT_FALSE(decodeBase64("aG=k", "t"));  // padding inside
  EXPECT_FALSE(decodeBase64("aG k", "t"));  // whitespace
}

}  // namespace
}  // namespace smpl
