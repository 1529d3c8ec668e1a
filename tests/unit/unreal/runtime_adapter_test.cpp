// The Unreal node's adapter (unreal/.../Public/SmplCorrectivesAdapter.h) with a
// stand-in skeleton in place of Unreal's: bones found by name among extra and
// prefixed bones, component-space rotations given as quaternions (x, y, z, w) in
// Unreal's mirrored axes, curves written per frame; checked against the
// reference forward pass (core/math/forward.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/models/model_loader.h"
#include "unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesAdapter.h"

namespace {

namespace sc = smpl_correctives;

// An imported skeleton as Unreal holds it: an extra "root" bone, namespaced
// joint names in another order, per-bone orientations, component space in
// Unreal's axes (C = unrealFbxAxes(), a mirror), rotations as quaternions.
struct StandInSkeleton {
  std::vector<std::string> names;
  std::vector<int> joint_of_bone;  // -1 for bones that are not model joints
  std::vector<Eigen::Matrix3d> orientation;
  Eigen::Matrix3d axes;

  StandInSkeleton(const smpl::BodyModel& model, const std::string& drop) {
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) axes(k, c) = sc::unrealFbxAxes()[size_t(3 * k + c)];
    names.push_back("root");
    joint_of_bone.push_back(-1);
    std::vector<int> order(model.parents.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = int(k);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    for (int k : order)
      if (model.joint_names[size_t(k)] != drop) {
        names.push_back("SMPL:" + model.joint_names[size_t(k)]);
        joint_of_bone.push_back(k);
      }
    Eigen::VectorXd aa = smpl::samplePoses(int(names.size()), 1, 21, 2.0)[0];
    for (size_t b = 0; b < names.size(); ++b)
      orientation.push_back(smpl::rodrigues(aa.segment<3>(Eigen::Index(3 * b))));
  }

  // Component-space rotation of bone b as Unreal's FQuat would give it.
  sc::Mat3 rotation(int b, const std::vector<Eigen::Matrix4d>& world) const {
    int k = joint_of_bone[size_t(b)];
    Eigen::Matrix3d g = k < 0 || world.empty()
                            ? Eigen::Matrix3d::Identity()
                            : Eigen::Matrix3d(world[size_t(k)].topLeftCorner<3, 3>());
    Eigen::Quaterniond q(Eigen::Matrix3d(axes * g * axes.transpose() * orientation[size_t(b)]));
    return sc::fromQuaternion(q.x(), q.y(), q.z(), q.w());
  }
};

const smpl::BodyModel& model() {
  static smpl::BodyModel m =
      *smpl::loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  return m;
}

sc::Layout splitLayout() {
  sc::Layout layout;
  layout.joint_names = model().joint_names;
  layout.parents = model().parents;
  for (int n = 0; n < layout.featureCount(); ++n) {
    if ((n % 9) % 4 == 0) {
      layout.correctives.push_back({"d" + std::to_string(n), n, -0.5, 0.0, false});
    } else {
      layout.correctives.push_back({"p" + std::to_string(n), n, 1.0, 0.0, true});
      layout.correctives.push_back({"n" + std::to_string(n), n, -1.0, 0.0, true});
    }
  }
  return layout;
}

// Curves written for one reference pose (local rotation of `rigid` forced to I).
std::map<std::string, double> curvesFor(const StandInSkeleton& skel, const sc::Layout& layout,
                                        uint64_t seed, const std::string& rigid,
                                        Eigen::VectorXd* features) {
  smpl::ForwardInput input;
  input.rotations =
      smpl::rotationsFromAxisAngle(smpl::samplePoses(int(model().parents.size()), 1, seed)[0]);
  for (size_t k = 0; k < input.rotations.size(); ++k)
    if (model().joint_names[k] == rigid) input.rotations[k] = Eigen::Matrix3d::Identity();
  smpl::ForwardResult ref = *smpl::forward(model(), input);
  *features = ref.pose_features;
  sc::BoneMap bones = sc::matchBones(layout, skel.names);
  sc::Evaluator ev;
  EXPECT_EQ(sc::bindSkeleton(&ev, layout, sc::unrealFbxAxes(), bones,
                             [&](int b) { return skel.rotation(b, {}); }),
            "");
  std::map<std::string, double> curves;
  std::vector<sc::Mat3> scratch;
  sc::driveFrame(
      ev, bones, [&](int b) { return skel.rotation(b, ref.world); },
      [&](size_t i, const std::string& name, double w) {
        EXPECT_EQ(name, ev.targetName(i));
        curves[name] = w;
      },
      &scratch);
  return curves;
}

TEST(RuntimeAdapter, CurvesFollowTheReferencePose) {
  StandInSkeleton skel(model(), "");
  sc::Layout layout = splitLayout();
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    Eigen::VectorXd f;
    std::map<std::string, double> curves = curvesFor(skel, layout, seed, "", &f);
    ASSERT_EQ(curves.size(), layout.correctives.size());
    for (const sc::Corrective& c : layout.correctives) {
      double w = c.scale * f(c.feature) + c.offset;
      EXPECT_NEAR(curves[c.target], c.rectified ? std::max(0.0, w) : w, 1e-12) << c.target;
      EXPECT_GE(curves[c.target], 0.0);
    }
  }
}

TEST(RuntimeAdapter, AJointWithoutABoneIsRigid) {
  const std::string dropped = model().joint_names[4];
  StandInSkeleton skel(model(), dropped);
  sc::BoneMap bones = sc::matchBones(splitLayout(), skel.names);
  EXPECT_TRUE(bones.missing[4]);
  EXPECT_EQ(bones.found, int(model().parents.size()) - 1);
  Eigen::VectorXd f;
  std::map<std::string, double> curves = curvesFor(skel, splitLayout(), 3, dropped, &f);
  for (const sc::Corrective& c : splitLayout().correctives) {
    double w = c.scale * f(c.feature) + c.offset;
    EXPECT_NEAR(curves[c.target], c.rectified ? std::max(0.0, w) : w, 1e-12) << c.target;
  }
}

// --skeleton-names: bones named otherwise than the joints are found through
// the metadata's bone_names, and the curves are the same.
TEST(RuntimeAdapter, RenamedBonesAreFoundThroughBoneNames) {
  StandInSkeleton skel(model(), "");
  sc::Layout layout = splitLayout();
  layout.bone_names.resize(layout.joint_names.size());
  for (size_t b = 0; b < skel.names.size(); ++b) {
    const int k = skel.joint_of_bone[b];
    if (k < 0) continue;
    skel.names[b] = "bone_" + std::to_string(k) + "_x";  // matches no joint name
    layout.bone_names[size_t(k)] = skel.names[b];
  }
  EXPECT_EQ(sc::matchBones(splitLayout(), skel.names).found, 0);  // by joint_names: none
  EXPECT_EQ(sc::matchBones(layout, skel.names).found, int(layout.joint_names.size()));
  Eigen::VectorXd f;
  std::map<std::string, double> curves = curvesFor(skel, layout, 2, "", &f);
  ASSERT_EQ(curves.size(), layout.correctives.size());
  for (const sc::Corrective& c : layout.correctives) {
    double w = c.scale * f(c.feature) + c.offset;
    EXPECT_NEAR(curves[c.target], c.rectified ? std::max(0.0, w) : w, 1e-12) << c.target;
  }
  // a namespaced bone name also matches the engine's name without the namespace
  sc::Layout mixamo;
  mixamo.joint_names = {"pelvis", "left_hip"};
  mixamo.bone_names = {"mixamorig:Hips", "mixamorig:LeftUpLeg"};
  mixamo.parents = {-1, 0};
  EXPECT_EQ(sc::matchBones(mixamo, {"root", "LeftUpLeg", "Hips", "pelvis"}).bone_of_joint,
            (std::vector<int>{2, 1}));
}

TEST(RuntimeAdapter, MatchesBonesByName) {
  sc::Layout layout;
  layout.joint_names = {"pelvis", "left_eye_smplhf", "jaw"};
  layout.parents = {-1, 0, 0};
  sc::BoneMap map =
      sc::matchBones(layout, {"root", "Armature|pelvis", "left_eye", "jaw_end", "body:jaw"});
  EXPECT_EQ(map.bone_of_joint, (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(map.found, 3);
  map = sc::matchBones(layout, {"left_eye_smplhf", "left_eye"});
  EXPECT_EQ(map.bone_of_joint,
            (std::vector<int>{-1, 0, -1}));  // the exact name wins over the alias
  sc::Evaluator ev;
  EXPECT_EQ(sc::bindSkeleton(&ev, layout, sc::identity(), sc::matchBones(layout, {"root"}),
                             [](int) { return sc::identity(); }),
            "skeleton: no bone is named after a joint of the metadata");
  EXPECT_EQ(sc::shortBoneName("a:b|c:pelvis"), "pelvis");
}

}  // namespace
