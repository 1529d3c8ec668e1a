#include "core/math/forward_batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/joint_names.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"
#include "core/models/model_loader.h"

namespace smpl {
namespace {

// SMPL's joint tree (24 joints, 207 pose features) with n vertices, random
// values: each vertex near a joint, posedirs of a few millimetres per unit
// feature (like SMPL's), and skin weights that are either dense Gaussians
// (every weight non-zero) or at most 3 influences per vertex, some vertices
// with one and vertex 5 (when n > 5) with none. n = 6890 is SMPL's size.
BodyModel smplLayoutTestModel(int n, bool sparse_weights, uint64_t seed = 17) {
  BodyModel m;
  m.kind = ModelKind::Smpl;
  m.name = "smpl-layout";
  m.parents = {-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21};
  m.joint_names = canonicalJointNames(ModelKind::Smpl);
  const int k = 24, p = 9 * (k - 1);
  const Eigen::VectorXd r =
      samplePoses(n * (3 * p + 3 + 30) / 3 + 100, 1, seed, 1.0)[0];  // uniforms in [-1, 1]
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
  if (sparse_weights) {
    m.weights = denseWeights(pruneWeights(m.weights, 3), k);
    for (int i = 0; i < n; i += 7) {  // one influence
      Eigen::Index j;
      m.weights.row(i).maxCoeff(&j);
      m.weights.row(i).setZero();
      m.weights(i, j) = 1.0;
    }
    if (n > 5) m.weights.row(5).setZero();  // none: forward() leaves it at the origin
  }
  Eigen::MatrixXd regressor = Eigen::MatrixXd::Zero(k, n);
  for (int i = 0; i < n; ++i) regressor(i % k, i) = 1.0 / ((n - 1 - i % k) / k + 1);
  m.j_regressor = regressor.sparseView();
  m.faces.resize(std::max(1, n - 2), 3);
  for (int f = 0; f < m.faces.rows(); ++f) m.faces.row(f) << f, (f + 1) % n, (f + 2) % n;
  m.posedirs = 0.005 * Eigen::Map<const Eigen::MatrixXd>(r.data() + 3 * n, 3 * n, p);
  m.shapedirs = 0.01 * Eigen::Map<const Eigen::MatrixXd>(r.data() + 3 * n * (p + 1), 3 * n, 10);
  return m;
}

// Largest |forwardBatch - forward()| over every frame and coordinate, metres.
double maxErrorVsForward(const BodyModel& model, const Eigen::VectorXd& betas,
                         const std::vector<Rotations>& frames, const Eigen::MatrixXd* weights,
                         const Eigen::MatrixXd& batch) {
  double worst = 0.0;
  for (size_t t = 0; t < frames.size(); ++t) {
    ForwardInput fi;
    fi.betas = betas;
    fi.rotations = frames[t];
    fi.weights = weights;
    Result<ForwardResult> ref = forward(model, fi);
    if (!ref.ok()) return INFINITY;
    Eigen::MatrixXd got =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
            batch.col(static_cast<Eigen::Index>(t)).data(), model.numVertices(), 3);
    worst = std::max(worst, (got - ref->vertices).cwiseAbs().maxCoeff());
    if (!std::isfinite(got.sum())) return INFINITY;
  }
  return worst;
}

// forwardBatch into a NaN-filled matrix of the result's shape (kept, not
// reallocated): an element a kernel fails to write stays NaN and fails the
// comparison, instead of holding the freed result of the previous kernel.
Eigen::MatrixXd batchIntoNan(const BodyModel& model, const BatchInput& in) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(
      3 * model.numVertices(), static_cast<Eigen::Index>(in.frames->size()), NAN);
  forwardBatch(model, in, &out);
  return out;
}

std::vector<Rotations> randomFrames(int joints, int count, uint64_t seed) {
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(joints, count, seed))
    frames.push_back(rotationsFromAxisAngle(pose));
  return frames;
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
  // Every kernel set the CPU runs (portable, AVX2, AVX-512), pruned and
  // full weights, blocks that end in a partial register tile (37 = 4*8+5
  // frames; block 8 = 6+2 for AVX2), 660 vertices (20 past the last whole
  // 32-vertex step), several threads.
  for (Kernels kernels : batch::supportedKernels()) {
    for (const Eigen::MatrixXd* weights :
         std::vector<const Eigen::MatrixXd*>{&pruned, &model->weights}) {
      for (int threads : {1, 3}) {
        BatchInput in{&*body, &frames, weights, threads, 8, kernels};
        Eigen::MatrixXd batch = batchIntoNan(*model, in);
        EXPECT_TRUE(batch.allFinite())
            << "unwritten elements, kernels " << batch::kernelsName(kernels);
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
              << "frame " << t << " threads " << threads << " kernels "
              << batch::kernelsName(kernels);
        }
      }
    }
  }
}

// The full-size layout (6890 vertices, 207 features, dense weights): the
// float arithmetic stays within 1e-6 m of forward() at the size that matters.
TEST(ForwardBatch, FullSizeSmplLayoutWithinMicrometre) {
  BodyModel model = smplLayoutTestModel(6890, /*sparse_weights=*/false);
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), 9, 3))
    frames.push_back(rotationsFromAxisAngle(pose));
  for (Kernels kernels : batch::supportedKernels()) {
    BatchInput in{&*body, &frames, nullptr, 1, 64, kernels};
    Eigen::MatrixXd batch = batchIntoNan(model, in);
    EXPECT_TRUE(batch.allFinite()) << "unwritten elements, kernels " << batch::kernelsName(kernels);
    for (size_t t = 0; t < frames.size(); ++t) {
      ForwardInput fi;
      fi.rotations = frames[t];
      Result<ForwardResult> ref = forward(model, fi);
      ASSERT_TRUE(ref.ok());
      Eigen::MatrixXd got =
          Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
              batch.col(t).data(), model.numVertices(), 3);
      EXPECT_LT((got - ref->vertices).cwiseAbs().maxCoeff(), 1e-6)
          << "frame " << t << " kernels " << batch::kernelsName(kernels);
    }
  }
}

// Every small fixture (SMPL 288 vertices, SMPL-H, SMPL-X 660, MANO 192;
// their weights have up to 6 influences), shaped, 13 frames (tails of the
// 8- and 6-frame tiles), every kernel set.
TEST(ForwardBatch, EverySmallFixtureEveryKernel) {
  for (const char* name : {"smpl_small", "smplh_small", "smplx_small", "mano_small"}) {
    Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/" + name + ".npz");
    ASSERT_TRUE(model.ok()) << name << ": " << model.message();
    const Eigen::VectorXd betas = Eigen::VectorXd::LinSpaced(4, -1, 1);
    Result<ShapedBody> body = shapeBody(*model, betas);
    ASSERT_TRUE(body.ok()) << name;
    const std::vector<Rotations> frames = randomFrames(model->numJoints(), 13, 21);
    for (Kernels kernels : batch::supportedKernels()) {
      BatchInput in{&*body, &frames, nullptr, 1, 64, kernels};
      EXPECT_LT(maxErrorVsForward(*model, betas, frames, nullptr, batchIntoNan(*model, in)), 1e-6)
          << name << ", kernels " << batch::kernelsName(kernels);
    }
  }
}

// Vertex counts around the 16-vertex blocks and 32-vertex steps and frame
// counts around the register tiles (8 frames AVX-512, 6 AVX2), dense and
// sparse weights (3 influences, single influences, a vertex with none),
// every kernel set, blocks that are whole tiles and blocks that are not.
TEST(ForwardBatch, EveryKernelOnVertexAndFrameTails) {
  for (int n : {1, 5, 15, 16, 17, 31, 32, 33, 47, 48, 63, 70}) {
    for (bool sparse : {false, true}) {
      const BodyModel model = smplLayoutTestModel(n, sparse, 100 + n);
      Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
      ASSERT_TRUE(body.ok());
      for (int count : {1, 7, 13}) {
        const std::vector<Rotations> frames = randomFrames(model.numJoints(), count, 9 + count);
        for (Kernels kernels : batch::supportedKernels()) {
          for (int block : {5, 8, 64}) {
            BatchInput in{&*body, &frames, nullptr, 1, block, kernels};
            const Eigen::MatrixXd batch = batchIntoNan(model, in);
            EXPECT_LT(maxErrorVsForward(model, Eigen::VectorXd(), frames, nullptr, batch), 1e-6)
                << n << " vertices, " << count << " frames, block " << block
                << (sparse ? ", sparse" : ", dense") << " weights, kernels "
                << batch::kernelsName(kernels);
          }
        }
      }
    }
  }
}

// The full-size layout with sparse weights: most steps skip most joints.
TEST(ForwardBatch, FullSizeSparseWeightsWithinMicrometre) {
  const BodyModel model = smplLayoutTestModel(6890, /*sparse_weights=*/true);
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  const std::vector<Rotations> frames = randomFrames(model.numJoints(), 11, 4);
  for (Kernels kernels : batch::supportedKernels()) {
    BatchInput in{&*body, &frames, nullptr, 1, 64, kernels};
    EXPECT_LT(maxErrorVsForward(model, Eigen::VectorXd(), frames, nullptr, batchIntoNan(model, in)),
              1e-6)
        << batch::kernelsName(kernels);
  }
}

// A set the CPU lacks is never run: it resolves to the widest it has,
// which is what Best picks; the portable set is always there.
TEST(ForwardBatch, KernelRequestsResolveToSetsTheCpuRuns) {
  const std::vector<Kernels> have = batch::supportedKernels();
  ASSERT_FALSE(have.empty());
  EXPECT_EQ(have.front(), Kernels::Portable);
  EXPECT_EQ(batch::resolveKernels(Kernels::Best), have.back());
  for (Kernels k : {Kernels::Portable, Kernels::Avx2, Kernels::Avx512}) {
    const Kernels got = batch::resolveKernels(k);
    EXPECT_TRUE(batch::cpuRuns(got)) << batch::kernelsName(k);
    EXPECT_EQ(got, batch::cpuRuns(k) ? k : have.back()) << batch::kernelsName(k);
  }
  EXPECT_TRUE(batch::cpuRuns(Kernels::Best));
}

// Writing into a caller's matrix: every element is written (a NaN-filled
// matrix of the right shape comes back equal to a fresh result), and the
// skins of forwardBatchSkins equal one forwardBatch per weight matrix; a
// posedirs packing made once (BatchInput::posedirs) gives the same result,
// and one of another model's size is ignored.
TEST(ForwardBatch, IntoExistingMatrixAndSeveralSkinsMatchFreshResults) {
  const BodyModel model = smplLayoutTestModel(70, /*sparse_weights=*/false);
  const Eigen::MatrixXd sparse = smplLayoutTestModel(70, /*sparse_weights=*/true).weights;
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  ASSERT_TRUE(body.ok());
  const std::vector<Rotations> frames = randomFrames(model.numJoints(), 19, 2);
  for (Kernels kernels : batch::supportedKernels()) {
    BatchInput in{&*body, &frames, nullptr, 2, 8, kernels};
    const Eigen::MatrixXd fresh = forwardBatch(model, in);
    Eigen::MatrixXd into = Eigen::MatrixXd::Constant(fresh.rows(), fresh.cols(), NAN);
    const double* memory = into.data();
    forwardBatch(model, in, &into);
    EXPECT_EQ(into.data(), memory) << "reallocated";
    EXPECT_TRUE(into == fresh) << batch::kernelsName(kernels);
    const std::vector<Eigen::MatrixXd> skins = forwardBatchSkins(model, in, {nullptr, &sparse});
    ASSERT_EQ(skins.size(), 2u);
    EXPECT_TRUE(skins[0] == fresh) << batch::kernelsName(kernels);
    in.weights = &sparse;
    EXPECT_TRUE(skins[1] == forwardBatch(model, in)) << batch::kernelsName(kernels);
    EXPECT_LT(maxErrorVsForward(model, Eigen::VectorXd(), frames, &sparse, skins[1]), 1e-6);
    in.weights = nullptr;
    const batch::PackedPosedirs packed = packPosedirs(model);
    in.posedirs = &packed;
    EXPECT_TRUE(forwardBatch(model, in) == fresh) << batch::kernelsName(kernels);
    const batch::PackedPosedirs other = packPosedirs(smplLayoutTestModel(40, false));
    in.posedirs = &other;
    EXPECT_TRUE(forwardBatch(model, in) == fresh) << batch::kernelsName(kernels);
  }
}

}  // namespace
}  // namespace smpl
