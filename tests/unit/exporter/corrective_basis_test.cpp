// --corrective-basis: the principal components of posedirs, checked against
// an independent SVD (Eigen's BDCSVD of posedirs itself), the weight bounds
// against sampled rotations, and the exported asset against v_shaped + P f.
#include "exporter/corrective_basis.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <nlohmann/json.hpp>

#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/models/model_loader.h"
#include "exporter/animation.h"
#include "exporter/metadata_json.h"
#include "exporter/pipeline.h"

namespace smpl {
namespace {

const std::string kFixtures = std::string(SMPL_FIXTURE_DIR);

BodyModel smallModel() {
  Result<BodyModel> m = loadModel(kFixtures + "/models/smpl_small.npz");
  EXPECT_TRUE(m.ok()) << m.message();
  return m.ok() ? *m : BodyModel();
}

TEST(CorrectiveBasis, OrthonormalAndExactAtFullRank) {
  const BodyModel model = smallModel();
  const int p = model.numPoseFeatures();
  Result<CorrectiveBasisFit> fit = fitCorrectiveBasis(model.posedirs, p);
  ASSERT_TRUE(fit.ok()) << fit.message();
  ASSERT_EQ(fit->basis.cols(), p);
  const Eigen::MatrixXd gram = fit->basis.transpose() * fit->basis;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(p, p)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((fit->basis * fit->projection - model.posedirs).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(CorrectiveBasis, LeadingSubspaceMatchesSvd) {
  const BodyModel model = smallModel();
  Eigen::BDCSVD<Eigen::MatrixXd> svd(model.posedirs, Eigen::ComputeThinU);
  for (int k : {1, 8, 32}) {
    Result<CorrectiveBasisFit> fit = fitCorrectiveBasis(model.posedirs, k);
    ASSERT_TRUE(fit.ok()) << fit.message();
    const Eigen::MatrixXd u = svd.matrixU().leftCols(k);
    // Same subspace: equal orthogonal projectors.
    const Eigen::MatrixXd ours = fit->basis * fit->basis.transpose(), theirs = u * u.transpose();
    EXPECT_LT((ours - theirs).cwiseAbs().maxCoeff(), 1e-8) << "K = " << k;
    for (int i = 0; i < k; ++i)
      EXPECT_NEAR(fit->variance(i), svd.singularValues()(i) * svd.singularValues()(i),
                  1e-9 * fit->variance(0));
  }
}

TEST(CorrectiveBasis, DeterministicWithSignConvention) {
  const BodyModel model = smallModel();
  Result<CorrectiveBasisFit> a = fitCorrectiveBasis(model.posedirs, 16);
  Result<CorrectiveBasisFit> b = fitCorrectiveBasis(model.posedirs, 16);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(a->basis == b->basis);
  EXPECT_TRUE(a->projection == b->projection);
  for (Eigen::Index k = 0; k < a->basis.cols(); ++k) {
    Eigen::Index at = 0;
    a->basis.col(k).cwiseAbs().maxCoeff(&at);
    EXPECT_GT(a->basis(at, k), 0.0) << "column " << k;
  }
}

TEST(CorrectiveBasis, RejectsBadK) {
  const BodyModel model = smallModel();
  EXPECT_FALSE(fitCorrectiveBasis(model.posedirs, 0).ok());
  Result<CorrectiveBasisFit> big = fitCorrectiveBasis(model.posedirs, 208);
  ASSERT_FALSE(big.ok());
  EXPECT_NE(big.message().find("--corrective-basis 208: expected 1..207"), std::string::npos)
      << big.message();
  // --corrective-basis with --correctives none: the request's conflict
  // (check_request_test.cpp); buildAsset then builds no basis.
}

// Rank-deficient posedirs: K is reduced to the rank, reconstruction stays exact.
TEST(CorrectiveBasis, RankDeficientKeepsRank) {
  Eigen::MatrixXd posedirs = Eigen::MatrixXd::Random(60, 18);
  posedirs.rightCols(9) = posedirs.leftCols(9) * Eigen::MatrixXd::Random(9, 9);  // rank 9
  Result<CorrectiveBasisFit> fit = fitCorrectiveBasis(posedirs, 18);
  ASSERT_TRUE(fit.ok()) << fit.message();
  EXPECT_EQ(fit->basis.cols(), 9);
  EXPECT_LT((fit->basis * fit->projection - posedirs).cwiseAbs().maxCoeff(), 1e-9);
}

// The Procrustes bound holds for sampled rotations and is nearly reached.
TEST(CorrectiveBasis, WeightRangeBoundsRotations) {
  Eigen::MatrixXd c = Eigen::MatrixXd::Random(2, 9);  // one joint, two components
  Eigen::VectorXd lo, hi;
  weightRange(c, &lo, &hi);
  uint64_t state = 7;
  Eigen::VectorXd seen_lo = Eigen::VectorXd::Zero(2), seen_hi = Eigen::VectorXd::Zero(2);
  for (int i = 0; i < 200000; ++i) {
    Eigen::Quaterniond q(uniform01(&state) - 0.5, uniform01(&state) - 0.5, uniform01(&state) - 0.5,
                         uniform01(&state) - 0.5);
    Rotations r = {Eigen::Matrix3d::Identity(), q.normalized().toRotationMatrix()};
    const Eigen::VectorXd w = c * poseFeatures(r);
    seen_lo = seen_lo.cwiseMin(w);
    seen_hi = seen_hi.cwiseMax(w);
  }
  for (int k = 0; k < 2; ++k) {
    EXPECT_GE(seen_lo(k), lo(k) - 1e-12);
    EXPECT_LE(seen_hi(k), hi(k) + 1e-12);
    EXPECT_LT(seen_lo(k) - lo(k), 0.03 * (hi(k) - lo(k)));
    EXPECT_LT(hi(k) - seen_hi(k), 0.03 * (hi(k) - lo(k)));
  }
}

// Mesh the asset gives at pose f: base + sum_k weight_k delta_k, in double.
Eigen::MatrixXd morphedMesh(const Asset& asset, const Eigen::VectorXd& weights) {
  Eigen::MatrixXd v = asset.mesh.positions.cast<double>();
  for (size_t k = 0; k < asset.mesh.morph_targets.size(); ++k)
    v += weights(k) * asset.mesh.morph_targets[k].deltas.cast<double>();
  return v;
}

Eigen::MatrixXd posedMesh(const BodyModel& model, const Eigen::MatrixXd& v_shaped,
                          const Eigen::VectorXd& f) {
  Eigen::VectorXd d = model.posedirs * f;
  return v_shaped + Eigen::Map<Eigen::MatrixXd>(d.data(), 3, model.numVertices()).transpose();
}

TEST(CorrectiveBasis, AssetReproducesPosedirsAtFullK) {
  const BodyModel model = smallModel();
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  for (CorrectiveEncoding enc : {CorrectiveEncoding::Signed, CorrectiveEncoding::Unit}) {
    ExportOptions o;
    o.encoding = enc;
    o.corrective_basis = model.numPoseFeatures();
    Result<Asset> asset = buildAsset(model, o);
    ASSERT_TRUE(asset.ok()) << asset.message();
    const CorrectiveBasis& b = asset->metadata.corrective_basis;
    ASSERT_EQ(asset->mesh.morph_targets.size(), 207u);
    EXPECT_EQ(asset->mesh.morph_targets[12].name, "pose_basis_12");
    EXPECT_TRUE(asset->metadata.correctives.empty());
    Eigen::VectorXd rest(207);
    for (int k = 0; k < 207; ++k) rest(k) = asset->mesh.morph_targets[k].rest_weight;
    EXPECT_LT((morphedMesh(*asset, rest) - body->v_shaped).cwiseAbs().maxCoeff(), 1e-5);
    const double lo = enc == CorrectiveEncoding::Unit ? 0.0 : -1.0;
    for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), 8, 3, 1.5)) {
      const Eigen::VectorXd f = poseFeatures(rotationsFromAxisAngle(pose));
      Eigen::VectorXd w = b.projection * f;
      for (int k = 0; k < 207; ++k) {
        w(k) = b.scale[k] * w(k) + b.offset[k];
        EXPECT_GE(w(k), lo - 1e-12);
        EXPECT_LE(w(k), 1.0 + 1e-12);
      }
      EXPECT_LT(
          (morphedMesh(*asset, w) - posedMesh(model, body->v_shaped, f)).cwiseAbs().maxCoeff(),
          1e-5);
    }
  }
}

TEST(CorrectiveBasis, AnimationWeightsAreScaledProjection) {
  const BodyModel model = smallModel();
  ExportOptions o;
  o.encoding = CorrectiveEncoding::Unit;
  o.corrective_basis = 32;
  o.shape_keys = 1;
  Result<Asset> asset = buildAsset(model, o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  Result<Motion> motion = loadMotion(kFixtures + "/motions/smpl_72.npz");
  ASSERT_TRUE(motion.ok()) << motion.message();
  Result<AnimationClip> clip = bakeAnimation(model, *asset, *motion, AnimationOptions(), "m.npz");
  ASSERT_TRUE(clip.ok()) << clip.message();
  ASSERT_EQ(clip->morph_weights.cols(), 33);
  const CorrectiveBasis& b = asset->metadata.corrective_basis;
  for (int i : {0, 7, 20}) {
    const Eigen::VectorXd f = poseFeatures(motion->frames[i]);
    for (int k : {0, 5, 31}) {
      double w = 0;
      for (int n = 0; n < 207; ++n) w += b.projection(k, n) * f(n);
      EXPECT_NEAR(clip->morph_weights(i, k), b.scale[k] * w + b.offset[k], 1e-6);
    }
    EXPECT_EQ(clip->morph_weights(i, 32), 0.0f);  // shape_0 is not driven
  }
}

TEST(CorrectiveBasis, MetadataCarriesMatrix) {
  const BodyModel model = smallModel();
  ExportOptions o;
  o.corrective_basis = 3;
  Result<Asset> asset = buildAsset(model, o);
  ASSERT_TRUE(asset.ok()) << asset.message();
  const nlohmann::json j = nlohmann::json::parse(metadataJson(*asset));
  ASSERT_TRUE(j.contains("corrective_basis"));
  const nlohmann::json& b = j["corrective_basis"];
  EXPECT_EQ(b["targets"],
            (std::vector<std::string>{"pose_basis_0", "pose_basis_1", "pose_basis_2"}));
  EXPECT_EQ(b["features"], 207);
  ASSERT_EQ(b["matrix"].size(), 3u * 207u);
  const Eigen::MatrixXd& c = asset->metadata.corrective_basis.projection;
  EXPECT_EQ(b["matrix"][207 + 5].get<double>(), c(1, 5));
  EXPECT_EQ(b["scale"].size(), 3u);
  EXPECT_EQ(b["offset"][2].get<double>(), 0.0);
  EXPECT_TRUE(j["correctives"].empty());
  Result<Asset> plain = buildAsset(model, ExportOptions());
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(nlohmann::json::parse(metadataJson(*plain)).contains("corrective_basis"));
}

TEST(CorrectiveBasis, ErrorReportShrinksToZero) {
  const BodyModel model = smallModel();
  const std::vector<BasisError> rows = basisErrorReport(model, {8, 32, 128, 207, 400}, 8, 11);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[4].components, 207);
  EXPECT_GT(rows[0].max_error, rows[1].max_error);
  EXPECT_GT(rows[1].mean_error, rows[2].mean_error);
  EXPECT_LT(rows[3].max_error, 1e-12);
  // Independent check of K = 8 at one pose: the residual of the SVD's U_8 projection.
  Eigen::BDCSVD<Eigen::MatrixXd> svd(model.posedirs, Eigen::ComputeThinU);
  const Eigen::MatrixXd u = svd.matrixU().leftCols(8);
  double max_err = 0;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), 8, 11)) {
    const Eigen::VectorXd d = model.posedirs * poseFeatures(rotationsFromAxisAngle(pose));
    const Eigen::VectorXd r = d - u * (u.transpose() * d);
    for (int i = 0; i < model.numVertices(); ++i)
      max_err = std::max(max_err, r.segment<3>(3 * i).norm());
  }
  EXPECT_NEAR(rows[0].max_error, max_err, 1e-9);
}

}  // namespace
}  // namespace smpl
