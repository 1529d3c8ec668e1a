// The C++ loaders of the runtime conformance kit (docs/conformance.md):
//  - UnrealCore: the Unreal plugin's header core (SmplCorrectivesMetadata.h
//    parseLayout reads each case's sidecar, SmplCorrectivesCore.h Evaluator
//    turns the engine's world rotations into features and weights) and its
//    answer to every bad sidecar;
//  - Exporter: the exporter's own weights, baked into an animation clip by
//    exportAsset from the case's model-space poses (float32 morph weight keys),
//    with the metadata's layout equal to the case's sidecar.
// The kit is $SMPL_CONFORMANCE_KIT, the model $SMPL_CONFORMANCE_MODEL.
#include <gtest/gtest.h>

#include <map>

#include "core/math/forward.h"
#include "core/models/model_loader.h"
#include "core/motions/motion.h"
#include "exporter/export_asset.h"
#include "tests/conformance/kit_reader.h"
#include "unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesMetadata.h"

namespace {

namespace sc = smpl_correctives;

std::vector<sc::Mat3> matrices(const std::vector<std::array<double, 4>>& q) {
  std::vector<sc::Mat3> out;
  for (const auto& v : q) out.push_back(sc::fromQuaternion(v[0], v[1], v[2], v[3]));
  return out;
}

/// "<case>: pose <i>: <what> differ by <e> (> <tol>)" when e > tol.
void expectClose(const std::string& name, size_t pose, const char* what, double e, double tol) {
  EXPECT_LE(e, tol) << name << ": pose " << pose << ": " << what << " differ by " << e << " (> "
                    << tol << ")";
}

TEST(UnrealCore, EveryCase) {
  kit::Kit k(kit::kitDir());
  const double tf = k.tolerance("features", "float64"), tw = k.tolerance("weights", "float64");
  size_t checked = 0;
  for (const kit::Case& c : k.cases()) {
    sc::Layout layout;
    std::string error = sc::parseLayout(c.sidecar, &layout);
    ASSERT_EQ(error, "") << c.name << ": sidecar";
    sc::Mat3 axes;
    std::copy(c.axes.begin(), c.axes.end(), axes.begin());
    sc::Evaluator ev;
    ASSERT_EQ(ev.bind(layout, axes, matrices(c.rest_world)), "") << c.name;
    for (size_t i = 0; i < c.poses.size(); ++i) {
      ev.evaluate(matrices(c.poses[i].world));
      expectClose(c.name, i, "features", kit::maxError(ev.features(), c.poses[i].features), tf);
      expectClose(c.name, i, "weights", kit::maxError(ev.weights(), c.poses[i].weights), tw);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0u);
}

TEST(UnrealCore, BadSidecarsAreRefusedNamingTheField) {
  kit::Kit k(kit::kitDir());
  std::vector<kit::Bad> bad = k.bad();
  ASSERT_FALSE(bad.empty());
  for (const kit::Bad& b : bad) {
    sc::Layout layout;
    std::string error = sc::parseLayout(b.text, &layout);
    EXPECT_NE(error, "") << b.name << ": accepted";
    if (b.error != "json") {
      EXPECT_NE(error.find(b.error), std::string::npos) << b.name << ": " << error;
    }
  }
}

/// A motion of the case's model-space poses (root included), in the model's layout.
smpl::Motion motionOf(const smpl::BodyModel& model, const kit::Case& c) {
  smpl::Motion m;
  m.name = "kit";
  m.layout = model.kind;
  for (const kit::Pose& p : c.poses) {
    Eigen::VectorXd aa =
        Eigen::Map<const Eigen::VectorXd>(p.axis_angle.data(), Eigen::Index(p.axis_angle.size()));
    m.frames.push_back(smpl::rotationsFromAxisAngle(aa));
    m.translation.push_back(Eigen::Vector3d::Zero());
  }
  return m;
}

smpl::ExportOptions optionsOf(const std::string& encoding) {
  smpl::ExportOptions o;
  o.encoding = encoding == "unit" || encoding == "basis" ? smpl::CorrectiveEncoding::Unit
               : encoding == "split"                     ? smpl::CorrectiveEncoding::Split
                                                         : smpl::CorrectiveEncoding::Signed;
  o.corrective_basis = encoding == "basis" ? 8 : 0;
  o.quantize_morphs = encoding == "signed_quantized";
  return o;
}

TEST(Exporter, BakedWeightsOfEveryCase) {
  kit::Kit k(kit::kitDir());
  const char* path = std::getenv("SMPL_CONFORMANCE_MODEL");
  ASSERT_TRUE(path) << "SMPL_CONFORMANCE_MODEL is not set";
  smpl::Result<smpl::BodyModel> model = smpl::loadModel(path);
  ASSERT_TRUE(model) << model.message();
  const double tw = k.tolerance("weights", "float32");
  size_t checked = 0;
  for (const kit::Case& c : k.cases()) {
    smpl::Motion motion = motionOf(*model, c);
    smpl::MotionInput in;
    in.motion = &motion;
    in.context = c.name;
    smpl::Result<smpl::Asset> asset = smpl::exportAsset(*model, optionsOf(c.encoding), {in});
    ASSERT_TRUE(asset) << c.name << ": " << asset.message();
    // The layout the exporter writes is the case's sidecar (parsed by the C++ runtimes' reader).
    sc::Layout layout;
    ASSERT_EQ(sc::parseLayout(c.sidecar, &layout), "") << c.name;
    const smpl::AssetMetadata& m = asset->metadata;
    ASSERT_EQ(m.correctives.size(), layout.correctives.size()) << c.name;
    ASSERT_EQ(m.corrective_basis.targets, layout.basis.targets) << c.name;
    std::map<std::string, size_t> index;
    for (size_t t = 0; t < asset->mesh.morph_targets.size(); ++t)
      index[asset->mesh.morph_targets[t].name] = t;
    std::vector<size_t> column;
    for (const sc::Corrective& e : layout.correctives) column.push_back(index.at(e.target));
    for (const std::string& t : layout.basis.targets) column.push_back(index.at(t));
    const Eigen::MatrixXf& w = asset->animations.at(0).morph_weights;
    ASSERT_EQ(size_t(w.rows()), c.poses.size()) << c.name;
    for (size_t i = 0; i < c.poses.size(); ++i) {
      std::vector<double> baked;
      for (size_t col : column) baked.push_back(w(Eigen::Index(i), Eigen::Index(col)));
      expectClose(c.name, i, "weights", kit::maxError(baked, c.poses[i].weights), tw);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0u);
}

}  // namespace
