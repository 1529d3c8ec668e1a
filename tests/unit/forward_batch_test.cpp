#include "core/math/forward_batch.h"

#include <gtest/gtest.h>

#include "core/load/model_loader.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"

namespace smpl {
namespace {

TEST(ForwardBatch, EqualsForwardForEveryFrameAndThreadCount) {
  Result<BodyModel> model = loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smplx_small.npz");
  ASSERT_TRUE(model.ok()) << model.message();
  Eigen::VectorXd betas = Eigen::VectorXd::LinSpaced(5, -1, 1);
  Result<ShapedBody> body = shapeBody(*model, betas);
  ASSERT_TRUE(body.ok());
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model->numJoints(), 37, 7)) frames.push_back(rotationsFromAxisAngle(pose));
  const Eigen::MatrixXd pruned = denseWeights(pruneWeights(model->weights, 4), model->numJoints());
  for (int threads : {1, 3}) {
    BatchInput in{&*body, &frames, &pruned, threads, 8};
    Eigen::MatrixXd batch = forwardBatch(*model, in);
    for (size_t t = 0; t < frames.size(); t += 5) {
      ForwardInput fi;
      fi.betas = betas;
      fi.rotations = frames[t];
      fi.weights = &pruned;
      Result<ForwardResult> ref = forward(*model, fi);
      ASSERT_TRUE(ref.ok());
      Eigen::MatrixXd got = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
          batch.col(t).data(), model->numVertices(), 3);
      // 1e-6: the corrective GEMM runs in float (forward_batch.h).
      EXPECT_LT((got - ref->vertices).cwiseAbs().maxCoeff(), 1e-6) << "frame " << t << " threads " << threads;
    }
  }
}

}  // namespace
}  // namespace smpl
