// The split corrective encoding (exporter/export_options.h, docs/file-contract.md):
// base mesh v_shaped, every weight 0 at rest and in [0, 1] for any pose, and
// sum_t max(0, scale f + offset) delta_t == posedirs f exactly (float deltas).
// Also: --corrective-basis targets are quantized by --quantize-morphs
// (exporter/morph_scales.h) with the scale folded into the basis mapping;
// the unit encoding's weights stay in [0, 1].
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/demo/demo_body.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "exporter/metadata_json.h"
#include "exporter/morph_scales.h"
#include "exporter/pipeline.h"

namespace smpl {
namespace {

double weightOf(const CorrectiveLayout& c, const Eigen::VectorXd& f) {
  const double w = c.scale * f[c.feature] + c.offset;
  return c.rectified ? std::max(0.0, w) : w;
}

TEST(SplitEncoding, ExactWithZeroRestWeightsAndUnitRange) {
  const BodyModel& model = demoBody();
  ExportOptions o;
  o.encoding = CorrectiveEncoding::Split;
  Result<Asset> asset = buildAsset(model, o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  const int joints = model.numJoints() - 1;
  ASSERT_EQ(asset->mesh.morph_targets.size(),
            size_t(15 * joints));  // 3 diagonal + 2 x 6 off-diagonal
  ASSERT_EQ(asset->metadata.correctives.size(), asset->mesh.morph_targets.size());
  EXPECT_EQ(asset->metadata.corrective_encoding, "split");
  EXPECT_EQ(asset->mesh.morph_targets[0].name, "pose_" + model.joint_names[1] + "_00");
  EXPECT_EQ(asset->mesh.morph_targets[1].name, "pose_" + model.joint_names[1] + "_01_pos");
  EXPECT_EQ(asset->mesh.morph_targets[2].name, "pose_" + model.joint_names[1] + "_01_neg");
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  EXPECT_LT((asset->mesh.positions.cast<double>() - body->v_shaped).cwiseAbs().maxCoeff(), 1e-6);
  for (size_t t = 0; t < asset->mesh.morph_targets.size(); ++t) {
    EXPECT_EQ(asset->mesh.morph_targets[t].rest_weight, 0.0f);
    EXPECT_TRUE(asset->metadata.correctives[t].rectified);
    EXPECT_EQ(asset->metadata.correctives[t].target, asset->mesh.morph_targets[t].name);
  }
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(model.numPoseFeatures());
  for (const CorrectiveLayout& c : asset->metadata.correctives) EXPECT_EQ(weightOf(c, rest), 0.0);
  for (const Eigen::VectorXd& pose :
       samplePoses(model.numJoints(), 8, 3, 3.0)) {  // large angles: f spans its range
    const Eigen::VectorXd f = poseFeatures(rotationsFromAxisAngle(pose));
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(model.numVertices(), 3);
    for (size_t t = 0; t < asset->mesh.morph_targets.size(); ++t) {
      const double w = weightOf(asset->metadata.correctives[t], f);
      EXPECT_GE(w, 0.0);
      EXPECT_LE(w, 1.0 + 1e-12);
      sum += w * asset->mesh.morph_targets[t].deltas.cast<double>();
    }
    const Eigen::VectorXd exact =  // the deltas the export writes (refitted where cut)
        (asset->corrective_refit->empty() ? model.posedirs
                                          : asset->corrective_refit->posedirs(model)) *
        f;
    for (int i = 0; i < model.numVertices(); ++i)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum(i, c), exact(3 * i + c), 1e-6);
  }
  const std::string json = metadataJson(*asset);
  EXPECT_NE(json.find("\"corrective_encoding\":\"split\""), std::string::npos);
  EXPECT_NE(json.find("\"rectified\":true"), std::string::npos);
}

TEST(SplitEncoding, OtherEncodingsAreNotRectified) {
  ExportOptions o;
  o.encoding = CorrectiveEncoding::Unit;
  Result<Asset> asset = buildAsset(demoBody(), o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  EXPECT_EQ(asset->metadata.corrective_encoding, "unit");
  EXPECT_EQ(metadataJson(*asset).find("rectified"), std::string::npos);
}

// The unit encoding keeps every weight in [0, 1] (docs/file-contract.md,
// "Encodings"): feature n is R_rc - delta_rc, so a diagonal feature lies in
// [-2, 0] and an off-diagonal one in [-1, 1]; weight = scale f + offset must
// map both ranges onto [0, 1], ends included. Checked at the range ends and on
// rotations up to pi (Eigen's AngleAxis, not the exporter's code).
TEST(UnitEncoding, WeightsStayInZeroOneAndTheRestPoseIsVShaped) {
  ExportOptions o;
  o.encoding = CorrectiveEncoding::Unit;
  Result<Asset> asset = buildAsset(demoBody(), o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  const std::vector<CorrectiveLayout>& layout = asset->metadata.correctives;
  ASSERT_FALSE(layout.empty());
  for (const CorrectiveLayout& c : layout) {
    const int entry = c.feature % 9;
    const bool diagonal = entry / 3 == entry % 3;
    const double lo = diagonal ? -2.0 : -1.0, hi = diagonal ? 0.0 : 1.0;
    EXPECT_NEAR(c.scale * lo + c.offset, 0.0, 1e-12) << c.target;
    EXPECT_NEAR(c.scale * hi + c.offset, 1.0, 1e-12) << c.target;
  }
  // At rest (f = 0) every weight is its offset, so the stored base mesh is
  // v_shaped minus sum_n offset_n delta_n: base + sum rest_weight delta = v_shaped.
  Result<ShapedBody> body = shapeBody(demoBody(), Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  const SkinnedMesh& mesh = asset->mesh;
  Eigen::MatrixXd rest = mesh.positions.cast<double>();
  for (const MorphTarget& t : mesh.morph_targets)
    rest += double(t.rest_weight) * t.deltas.cast<double>();
  double worst = 0;
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::fabs(rest(i, c) - body->v_shaped(mesh.source_vertex[i], c)));
  EXPECT_LT(worst, 1e-5) << "metres";
  uint64_t state = 7;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3d axis =
        Eigen::Vector3d(uniform01(&state) - 0.5, uniform01(&state) - 0.5, uniform01(&state) - 0.5)
            .normalized();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(M_PI * uniform01(&state), axis).toRotationMatrix();
    for (const CorrectiveLayout& c : layout) {
      const int entry = c.feature % 9;
      const double f = r(entry / 3, entry % 3) - (entry / 3 == entry % 3 ? 1.0 : 0.0);
      const double w = c.scale * f + c.offset;
      ASSERT_GE(w, -1e-12) << c.target;
      ASSERT_LE(w, 1.0 + 1e-12) << c.target;
    }
  }
}

// The split encoding with a corrective basis is refused by the request
// (check_request_test.cpp: "--corrective-basis conflicts with
// --corrective-weights split"), before buildAsset.

// Sum of every basis target's weight times delta for feature vector f.
Eigen::MatrixXd basisOffset(const Asset& a, const Eigen::VectorXd& f) {
  const CorrectiveBasis& b = a.metadata.corrective_basis;
  std::map<std::string, size_t> index;
  for (size_t t = 0; t < a.mesh.morph_targets.size(); ++t) index[a.mesh.morph_targets[t].name] = t;
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(a.mesh.positions.rows(), 3);
  const Eigen::VectorXd cf = b.projection * f;
  for (size_t k = 0; k < b.targets.size(); ++k)
    sum += (b.scale[k] * cf[Eigen::Index(k)] + b.offset[k]) *
           a.mesh.morph_targets[index.at(b.targets[k])].deltas.cast<double>();
  return sum;
}

TEST(QuantizeMorphs, CorrectiveBasisTargetsAreQuantizedAndFolded) {
  ExportOptions o;
  o.corrective_basis = 6;
  Result<Asset> asset = buildAsset(demoBody(), o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  const std::vector<bool> q = quantizedTargets(*asset);
  ASSERT_EQ(q.size(), 6u);
  for (bool b : q) EXPECT_TRUE(b);  // before: no basis target was quantized
  Asset folded = *asset;
  foldMorphScales(&folded);
  for (const MorphTarget& t : folded.mesh.morph_targets)
    EXPECT_FLOAT_EQ(t.deltas.cwiseAbs().maxCoeff(), 1.0f);
  for (size_t k = 0; k < 6; ++k)
    EXPECT_NE(folded.metadata.corrective_basis.scale[k], asset->metadata.corrective_basis.scale[k]);
  const Eigen::VectorXd f =
      poseFeatures(rotationsFromAxisAngle(samplePoses(demoBody().numJoints(), 1, 5)[0]));
  EXPECT_LT((basisOffset(folded, f) - basisOffset(*asset, f)).cwiseAbs().maxCoeff(), 1e-6);
}

}  // namespace
}  // namespace smpl
