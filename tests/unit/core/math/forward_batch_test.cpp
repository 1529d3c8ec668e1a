#include "core/math/forward_batch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/joint_names.h"
#include "core/load/model_loader.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"

namespace smpl {
namespace {

// SMPL's layout at full size (6890 vertices, 24 joints, 207 pose features),
// random values: each vertex near a joint, dense Gaussian skin weights,
// posedirs of a few millimetres per unit feature (like SMPL's).
BodyModel fullSizeTestModel() {
  BodyModel m;
  m.kind = ModelKind::Smpl;
  m.name = "full-size";
  m.parents = {-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21};
  m.joint_names = canonicalJointNames(ModelKind::Smpl);
  const int n = 6890, k = 24, p = 9 * (k - 1);
  const Eigen::VectorXd r =
      samplePoses(n * (3 * p + 3 + 30) / 3 + 1, 1, 17, 1.0)[0];  // uniforms in [-1, 1]
  Eigen::MatrixXd joints(k, 3);
  joints.row(0) << 0, 0.9, 0;
  for (int j = 1; j < k; ++j)
    joints.row(j) = joints.row(m.parents[j]) + 0.1 * r.segment<3>(3 * j).transpose();
  m.v_template.resize(n, 3);
  for (int i = 0; i < n; ++i)
    m.v_template.row(i) = joints.row(i % k) + 0.05 * r.segment<3>(3 * i + 100).transpose();
  m.weights.resize(n, k);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j)
      m.weights(i, j) = std::exp(-(m.v_template.row(i) - joints.row(j)).squaredNorm() / 0.01);
    m.weights.row(i) /= m.weights.row(i).sum();
  }
  Eigen::MatrixXd regressor = Eigen::MatrixXd::Zero(k, n);
  for (int i = 0; i < n; ++i) regressor(i % k, i) = 1.0 / ((n - 1 - i % k) / k + 1);
  m.j_regressor = regressor.sparseView();
  m.faces.resize(n - 2, 3);
  for (int f = 0; f < n - 2; ++f) m.faces.row(f) << f, f + 1, f + 2;
  m.posedirs = 0.005 * Eigen::Map<const Eigen::MatrixXd>(r.data() + 3 * n, 3 * n, p);
  m.shapedirs = 0.01 * Eigen::Map<const Eigen::MatrixXd>(r.data() + 3 * n * (p + 1), 3 * n, 10);
  return m;
}

TEST(ForwardBatch, EqualsForwardForEveryFrameAndThreadCount) {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smplx_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  Eigen::VectorXd betas = Eigen::VectorXd::LinSpaced(5, -1, 1);
  Result<ShapedBody> body = shapeBody(*model, betas);
  ASSERT_TRUE(body.ok());
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model->numJoints(), 37, 7))
    frames.push_back(rotationsFromAxisAngle(pose));
  const Eigen::MatrixXd pruned = denseWeights(pruneWeights(model->weights, 4), model->numJoints());
  // Every kernel (AVX2 where the CPU has it, and the portable one), pruned
  // and full weights, blocks that end in a partial register tile (37 = 4*8+5
  // frames; block 8 = 6+2), several threads.
  for (bool simd : {true, false}) {
    for (const Eigen::MatrixXd* weights :
         std::vector<const Eigen::MatrixXd*>{&pruned, &model->weights}) {
      for (int threads : {1, 3}) {
        BatchInput in{&*body, &frames, weights, threads, 8, simd};
        Eigen::MatrixXd batch = forwardBatch(*model, in);
        for (size_t t = 0; t < frames.size(); ++t) {
          ForwardInput fi;
          fi.betas = betas;
          fi.rotations = frames[t];
          fi.weights = weights;
          Result<ForwardResult> ref = forward(*model, fi);
          ASSERT_TRUE(ref.ok());
          Eigen::MatrixXd got =
              Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
                  batch.col(t).data(), model->numVertices(), 3);
          // 1e-6 m: the corrective GEMM and the transform blend run in float (forward_batch.h).
          EXPECT_LT((got - ref->vertices).cwiseAbs().maxCoeff(), 1e-6)
              << "frame " << t << " threads " << threads << " simd " << simd;
        }
      }
    }
  }
}

// The full-size layout (6890 vertices, 207 features, dense weights): the
// float arithmetic stays within 1e-6 m of forward() at the size that matters.
TEST(ForwardBatch, FullSizeSmplLayoutWithinMicrometre) {
  BodyModel model = fullSizeTestModel();
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), 9, 3))
    frames.push_back(rotationsFromAxisAngle(pose));
  for (bool simd : {true, false}) {
    BatchInput in{&*body, &frames, nullptr, 1, 64, simd};
    Eigen::MatrixXd batch = forwardBatch(model, in);
    for (size_t t = 0; t < frames.size(); ++t) {
      ForwardInput fi;
      fi.rotations = frames[t];
      Result<ForwardResult> ref = forward(model, fi);
      ASSERT_TRUE(ref.ok());
      Eigen::MatrixXd got =
          Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
              batch.col(t).data(), model.numVertices(), 3);
      EXPECT_LT((got - ref->vertices).cwiseAbs().maxCoeff(), 1e-6)
          << "frame " << t << " simd " << simd;
    }
  }
}

}  // namespace
}  // namespace smpl
