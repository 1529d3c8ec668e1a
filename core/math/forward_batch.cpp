#include "core/math/forward_batch.h"

#include <algorithm>
#include <thread>
#include <utility>

#include "core/math/forward_batch_kernels.h"

namespace smpl {
namespace {

// Top 3x4 rows of A_k = G_k [I | -J_k], one row of 12 per joint.
Eigen::Matrix<double, Eigen::Dynamic, 12> restRelative(const BodyModel& model, const Rotations& rot,
                                                       const Eigen::MatrixXd& joints) {
  const int k = model.numJoints();
  std::vector<Eigen::Matrix<double, 3, 4>> world(k);
  Eigen::Matrix<double, Eigen::Dynamic, 12> a(k, 12);
  for (int j = 0; j < k; ++j) {
    const int p = model.parents[j];
    Eigen::Vector3d offset =
        joints.row(j).transpose() -
        (p >= 0 ? Eigen::Vector3d(joints.row(p).transpose()) : Eigen::Vector3d::Zero());
    if (p < 0) {
      world[j] << rot[j], offset;
    } else {
      world[j].leftCols<3>() = world[p].leftCols<3>() * rot[j];
      world[j].col(3) = world[p].leftCols<3>() * offset + world[p].col(3);
    }
    Eigen::Matrix<double, 3, 4> aj;
    aj << world[j].leftCols<3>(),
        world[j].col(3) - world[j].leftCols<3>() * joints.row(j).transpose();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) a(j, 4 * r + c) = aj(r, c);
  }
  return a;
}

using Transforms = Eigen::Matrix<float, Eigen::Dynamic, 12, Eigen::RowMajor>;

// One block of frames: the corrective GEMM once, then the skinning of every
// frame with each weight set into its output.
void runBlock(const BodyModel& model, const batch::PackedPosedirs& posedirs, const BatchInput& in,
              const std::vector<Eigen::MatrixXf>& weights, bool simd, int first, int count,
              std::vector<Eigen::MatrixXd>* out) {
  const int n = static_cast<int>(model.numVertices()), p = model.numPoseFeatures();
  Eigen::MatrixXf features(p, count);
  for (int t = 0; t < count; ++t)
    features.col(t) = poseFeatures((*in.frames)[first + t]).cast<float>();
  Eigen::MatrixXf v_posed(posedirs.rows_padded, count);  // the correctives, one column per frame
  batch::correctiveProduct(posedirs, features.data(), count, v_posed.data(), simd);
  for (int t = 0; t < count; ++t) {
    const Transforms a =
        restRelative(model, (*in.frames)[first + t], in.body->joints).cast<float>();
    for (size_t s = 0; s < weights.size(); ++s)
      batch::skinFrame(weights[s].data(), n, model.numJoints(), a.data(), in.body->v_shaped.data(),
                       v_posed.col(t).data(), (*out)[s].col(first + t).data(), simd);
  }
}

}  // namespace

std::vector<Eigen::MatrixXd> forwardBatchSkins(const BodyModel& model, const BatchInput& in,
                                               const std::vector<const Eigen::MatrixXd*>& skins) {
  const int frames = static_cast<int>(in.frames->size());
  std::vector<Eigen::MatrixXf> weights;
  std::vector<Eigen::MatrixXd> out;
  for (const Eigen::MatrixXd* w : skins) {
    weights.push_back((w ? *w : model.weights).cast<float>());
    out.emplace_back(3 * model.numVertices(), frames);
  }
  const batch::PackedPosedirs posedirs =
      batch::packPosedirs(model.posedirs.data(), static_cast<int>(model.posedirs.rows()),
                          static_cast<int>(model.posedirs.cols()));
  const bool simd = in.simd && batch::haveAvx2Fma();
  const int block = std::max(1, in.block);
  const int blocks = (frames + block - 1) / block;
  auto work = [&](int worker, int workers) {
    for (int b = worker; b < blocks; b += workers)
      runBlock(model, posedirs, in, weights, simd, b * block, std::min(block, frames - b * block),
               &out);
  };
  const int workers = std::max(1, std::min(in.threads, blocks));
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w, workers);
  work(0, workers);
  for (std::thread& t : pool) t.join();
  return out;
}

Eigen::MatrixXd forwardBatch(const BodyModel& model, const BatchInput& in) {
  return std::move(forwardBatchSkins(model, in, {in.weights}).front());
}

}  // namespace smpl
