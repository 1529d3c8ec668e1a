// The Unreal plugin's glue (FAnimNode_SmplCorrectives, AnimNode_SmplCorrectives.cpp,
// and the editor node) compiled against stand-in Unreal types
// (tests/runtimes/unreal_standin/) and run on a stand-in skeleton: the metadata
// from MetadataJson or MetadataFile, bones found in the reference skeleton,
// component space composed from local rotations, curves written per frame,
// checked against the reference forward pass. Not Unreal: see unreal/README.md.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "AnimGraphNode_SmplCorrectives.h"
#include "AnimNode_SmplCorrectives.h"
#include "Animation/AnimInstanceProxy.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/models/model_loader.h"

namespace {

namespace sc = smpl_correctives;

const smpl::BodyModel& model() {
  static smpl::BodyModel m =
      *smpl::loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  return m;
}

FQuat toQuat(const Eigen::Matrix3d& m) {
  Eigen::Quaterniond q(m);
  return FQuat(q.x(), q.y(), q.z(), q.w());
}

// The split encoding's metadata (common brief) for the fixture model.
nlohmann::json splitMetadata() {
  nlohmann::json m;
  m["joint_names"] = model().joint_names;
  m["parents"] = model().parents;
  m["up_axis"] = "+Y";
  m["corrective_encoding"] = "split";
  for (int n = 0; n < 9 * (int(model().parents.size()) - 1); ++n) {
    std::string base = "pose_" + model().joint_names[size_t(n / 9 + 1)] + "_" +
                       std::to_string((n % 9) / 3) + std::to_string(n % 3);
    if ((n % 9) % 4 == 0) {
      m["correctives"].push_back(
          {{"feature", n}, {"target", base}, {"scale", -0.5}, {"offset", 0}});
    } else {
      m["correctives"].push_back(
          {{"feature", n}, {"target", base + "_pos"}, {"scale", 1}, {"rectified", true}});
      m["correctives"].push_back(
          {{"feature", n}, {"target", base + "_neg"}, {"scale", -1}, {"rectified", true}});
    }
  }
  return m;
}

// Unreal's imported skeleton: "root" bone 0, joints as children with random
// reference-pose orientations; component space in Unreal's axes (a mirror).
struct Rig {
  FAnimInstanceProxy proxy;
  std::vector<Eigen::Matrix3d> orientation;  // per bone, component space at rest
  Eigen::Matrix3d axes;

  Rig() {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) axes(r, c) = sc::unrealFbxAxes()[size_t(3 * r + c)];
    FReferenceSkeleton& ref = proxy.Required.Reference;
    ref.Names.push_back("root");
    ref.Parents.push_back(-1);
    for (size_t k = 0; k < model().parents.size(); ++k) {
      ref.Names.push_back(model().joint_names[k]);
      ref.Parents.push_back(model().parents[k] + 1);  // bone = joint + 1; pelvis under root
    }
    Eigen::VectorXd aa = smpl::samplePoses(ref.GetNum(), 1, 17, 2.0)[0];
    for (int b = 0; b < ref.GetNum(); ++b)
      orientation.push_back(smpl::rodrigues(aa.segment<3>(3 * b)));
    ref.RefPose = localPose({});
  }

  // Local rotations whose component-space composition is (C G_k C^-1) O_b.
  std::vector<FTransform> localPose(const std::vector<Eigen::Matrix4d>& world) const {
    const FReferenceSkeleton& ref = proxy.Required.Reference;
    std::vector<Eigen::Matrix3d> component;
    std::vector<FTransform> local;
    for (int b = 0; b < ref.GetNum(); ++b) {
      Eigen::Matrix3d g = b == 0 || world.empty()
                              ? Eigen::Matrix3d::Identity()
                              : Eigen::Matrix3d(world[size_t(b - 1)].topLeftCorner<3, 3>());
      component.push_back(axes * g * axes.transpose() * orientation[size_t(b)]);
      int p = ref.Parents[size_t(b)];
      local.emplace_back(
          toQuat(p < 0 ? component.back()
                       : Eigen::Matrix3d(component[size_t(p)].transpose() * component.back())));
    }
    return local;
  }
};

void runNode(FAnimNode_SmplCorrectives& node, Rig& rig, uint64_t seed, FPoseContext* out,
             Eigen::VectorXd* features) {
  smpl::ForwardInput input;
  input.rotations =
      smpl::rotationsFromAxisAngle(smpl::samplePoses(int(model().parents.size()), 1, seed)[0]);
  smpl::ForwardResult ref = *smpl::forward(model(), input);
  *features = ref.pose_features;
  node.Source.Produce = [&](FPoseContext& pose) {
    pose.Pose.Bones = &rig.proxy.Required;
    pose.Pose.Local = rig.localPose(ref.world);
  };
  node.Update_AnyThread(FAnimationUpdateContext());
  node.Evaluate_AnyThread(*out);
}

void initialise(FAnimNode_SmplCorrectives& node, Rig& rig) {
  node.Initialize_AnyThread(FAnimationInitializeContext());
  FAnimationCacheBonesContext cache;
  cache.AnimInstanceProxy = &rig.proxy;
  node.CacheBones_AnyThread(cache);
}

void expectCurves(const nlohmann::json& meta, const FPoseContext& out, const Eigen::VectorXd& f,
                  float alpha) {
  ASSERT_EQ(out.Curve.Values.size(), meta["correctives"].size());
  for (const nlohmann::json& e : meta["correctives"]) {
    double w = e["scale"].get<double>() * f(e["feature"].get<int>());
    if (e.value("rectified", false)) w = std::max(0.0, w);
    EXPECT_NEAR(out.Curve.Values.at(e["target"].get<std::string>()), alpha * w, 1e-6)
        << e["target"];
  }
}

TEST(UnrealStandIn, NodeWritesTheCorrectiveCurves) {
  Rig rig;
  FAnimNode_SmplCorrectives node;
  nlohmann::json meta = splitMetadata();
  node.MetadataJson = FString(meta.dump());
  initialise(node, rig);
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    FPoseContext out;
    Eigen::VectorXd f;
    runNode(node, rig, seed, &out, &f);
    expectCurves(meta, out, f, 1.0f);
  }
  FNodeDebugData debug;
  node.GatherDebugData(debug);
  EXPECT_EQ(debug.Items.at(0), "SmplCorrectives(24 joints, " +
                                   std::to_string(meta["correctives"].size()) + " curves)");
}

TEST(UnrealStandIn, MetadataFromFileAndAlpha) {
  Rig rig;
  nlohmann::json meta = splitMetadata();
  std::string path = ::testing::TempDir() + "/unreal_standin_body.fbx.smpl.json";
  std::ofstream(path) << meta.dump();
  FAnimNode_SmplCorrectives node;
  node.MetadataFile.FilePath = FString(path);
  node.Alpha = 0.5f;
  initialise(node, rig);
  FPoseContext out;
  Eigen::VectorXd f;
  runNode(node, rig, 5, &out, &f);
  expectCurves(meta, out, f, 0.5f);
  std::remove(path.c_str());
}

TEST(UnrealStandIn, WrongAxesGiveWrongCurves) {
  Rig rig;
  FAnimNode_SmplCorrectives node;
  const nlohmann::json meta = splitMetadata();
  node.MetadataJson = FString(meta.dump());
  node.AxisPreset = ESmplAxisPreset::Identity;
  initialise(node, rig);
  FPoseContext out;
  Eigen::VectorXd f;
  runNode(node, rig, 2, &out, &f);
  double worst = 0;
  ASSERT_EQ(out.Curve.Values.size(), meta["correctives"].size());
  for (const nlohmann::json& e : meta["correctives"]) {
    double w = e["scale"].get<double>() * f(e["feature"].get<int>());
    if (e.value("rectified", false)) w = std::max(0.0, w);
    worst = std::max(worst, std::fabs(out.Curve.Values.at(e["target"].get<std::string>()) - w));
  }
  EXPECT_GT(worst, 0.05);
}

TEST(UnrealStandIn, ProblemsAreReportedAndNothingIsWritten) {
  Rig rig;
  FAnimNode_SmplCorrectives node;
  initialise(node, rig);
  FPoseContext out;
  Eigen::VectorXd f;
  runNode(node, rig, 1, &out, &f);
  EXPECT_TRUE(out.Curve.Values.empty());
  FNodeDebugData debug;
  node.GatherDebugData(debug);
  EXPECT_NE(debug.Items.at(0).find("no metadata"), std::string::npos) << debug.Items.at(0);

  FAnimNode_SmplCorrectives bad;
  bad.MetadataJson = FString("{\"joint_names\": [\"pelvis\"], \"parents\": [0]}");
  initialise(bad, rig);
  runNode(bad, rig, 1, &out, &f);
  EXPECT_TRUE(out.Curve.Values.empty());
  EXPECT_NE(StandInLog().back().find("metadata: 'parents'[0] must be -1"), std::string::npos)
      << StandInLog().back();
}

TEST(UnrealStandIn, EditorNodeDescribesItself) {
  UAnimGraphNode_SmplCorrectives node;
  EXPECT_EQ(node.GetNodeTitle(ENodeTitleType::FullTitle).Text, "SMPL Correctives");
  EXPECT_EQ(node.GetNodeCategory().Std(), "SMPL");
}

}  // namespace
