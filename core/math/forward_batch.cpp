#include "core/math/forward_batch.h"

#include <algorithm>
#include <thread>
#include <utility>

#include "core/huge_pages.h"
#include "core/parallel.h"

namespace smpl {
namespace {

// Pose features and the top 3x4 rows of A_k = G_k [I | -J_k] of one frame,
// in double, written as float: f (P values, row-major vec(R_k - I) for
// k = 1..K-1, zero past 9(K-1)) and a (K x 12, joint by joint, row by row).
// world: 12 K doubles of scratch (each joint's world rotation and origin).
void frameInputs(const std::vector<int>& parents, const Rotations& rot, const double* joints, int p,
                 double* world, float* f, float* a) {
  const int k = static_cast<int>(parents.size());
  for (int i = 0; i < p; ++i) f[i] = 0.0f;
  for (int j = 1; j < k; ++j)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const int i = 9 * (j - 1) + 3 * r + c;
        if (i < p) f[i] = static_cast<float>(rot[j](r, c) - (r == c ? 1.0 : 0.0));
      }
  auto joint = [&](int j, int c) { return joints[static_cast<size_t>(c) * k + j]; };  // K x 3
  for (int j = 0; j < k; ++j) {
    const int par = parents[j];
    double* w = world + 12 * j;  // R (row-major 3x3) then origin
    const Eigen::Matrix3d& r = rot[j];
    if (par < 0) {
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) w[3 * x + y] = r(x, y);
      for (int x = 0; x < 3; ++x) w[9 + x] = joint(j, x);
    } else {
      const double* pw = world + 12 * par;
      double offset[3];
      for (int x = 0; x < 3; ++x) offset[x] = joint(j, x) - joint(par, x);
      for (int x = 0; x < 3; ++x) {
        for (int y = 0; y < 3; ++y)
          w[3 * x + y] = pw[3 * x] * r(0, y) + pw[3 * x + 1] * r(1, y) + pw[3 * x + 2] * r(2, y);
        w[9 + x] = pw[3 * x] * offset[0] + pw[3 * x + 1] * offset[1] + pw[3 * x + 2] * offset[2] +
                   pw[9 + x];
      }
    }
    float* aj = a + 12 * j;
    for (int x = 0; x < 3; ++x) {
      for (int y = 0; y < 3; ++y) aj[4 * x + y] = static_cast<float>(w[3 * x + y]);
      aj[4 * x + 3] = static_cast<float>(w[9 + x] - w[3 * x] * joint(j, 0) -
                                         w[3 * x + 1] * joint(j, 1) - w[3 * x + 2] * joint(j, 2));
    }
  }
}

// One block of frames: each frame's features and transforms, then the
// kernels (the corrective GEMM once, the skinning with each weight set).
void runBlock(const BodyModel& model, const batch::PackedPosedirs& posedirs,
              const std::vector<const batch::PackedSkin*>& skins, const batch::PackedRest& rest,
              const BatchInput& in, Kernels kernels, int first, int count,
              const std::vector<Eigen::MatrixXd*>& out) {
  const int k = model.numJoints(), p = posedirs.depth;
  std::vector<float> features(static_cast<size_t>(p) * count), transforms(12 * k * count);
  std::vector<double> world(12 * k);
  for (int t = 0; t < count; ++t)
    frameInputs(model.parents, (*in.frames)[first + t], in.body->joints.data(), p, world.data(),
                features.data() + static_cast<size_t>(t) * p, transforms.data() + 12 * k * t);
  std::vector<double*> dst;
  for (Eigen::MatrixXd* o : out) dst.push_back(o->col(first).data());
  batch::FrameBlock block;
  block.features = features.data();
  block.transforms = transforms.data();
  block.frames = count;
  block.joints = k;
  batch::evaluateBlock(posedirs, skins, rest, block, dst.data(),
                       3 * static_cast<size_t>(model.numVertices()), kernels);
}

void run(const BodyModel& model, const BatchInput& in,
         const std::vector<const Eigen::MatrixXd*>& weights,
         const std::vector<Eigen::MatrixXd*>& out) {
  const int n = model.numVertices(), frames = static_cast<int>(in.frames->size());
  for (Eigen::MatrixXd* o : out)
    if (o->rows() != 3 * n || o->cols() != frames) {
      o->resize(3 * n, frames);  // not touched yet: Eigen does not initialise
      adviseHugePages(o->data(), static_cast<size_t>(o->size()) * sizeof(double));
    }
  if (frames == 0 || n == 0) return;
  std::vector<batch::PackedSkin> packed;
  packed.reserve(weights.size());
  for (const Eigen::MatrixXd* w : weights)
    packed.push_back(batch::packSkin((w ? *w : model.weights).data(), n, model.numJoints()));
  std::vector<const batch::PackedSkin*> skins;
  for (const batch::PackedSkin& s : packed) skins.push_back(&s);
  const int depth = static_cast<int>(model.posedirs.cols());
  const bool reuse = in.posedirs && in.posedirs->vertices == n && in.posedirs->depth == depth &&
                     in.posedirs->steps == (n + batch::kStepVertices - 1) / batch::kStepVertices &&
                     in.posedirs->data.size() ==
                         static_cast<size_t>(in.posedirs->steps) * batch::kStepRows * depth;
  const batch::PackedPosedirs own =
      reuse ? batch::PackedPosedirs() : packPosedirs(model, std::max(1, in.threads));
  const batch::PackedPosedirs& posedirs = reuse ? *in.posedirs : own;
  const batch::PackedRest rest = batch::packRest(in.body->v_shaped.data(), n);
  const Kernels kernels = batch::resolveKernels(in.kernels);
  const int block = std::max(1, in.block);
  const int blocks = (frames + block - 1) / block;
  auto work = [&](int worker, int workers) {
    for (int b = worker; b < blocks; b += workers)
      runBlock(model, posedirs, skins, rest, in, kernels, b * block,
               std::min(block, frames - b * block), out);
  };
  const int workers = std::max(1, std::min(in.threads, blocks));
  runWorkers(workers, work);
}

}  // namespace

batch::PackedPosedirs packPosedirs(const BodyModel& model, int threads) {
  return batch::packPosedirs(model.posedirs.data(), model.numVertices(),
                             static_cast<int>(model.posedirs.cols()), threads);
}

std::vector<Eigen::MatrixXd> forwardBatchSkins(const BodyModel& model, const BatchInput& in,
                                               const std::vector<const Eigen::MatrixXd*>& skins) {
  std::vector<Eigen::MatrixXd> out(skins.size());
  std::vector<Eigen::MatrixXd*> dst;
  for (Eigen::MatrixXd& o : out) dst.push_back(&o);
  run(model, in, skins, dst);
  return out;
}

void forwardBatch(const BodyModel& model, const BatchInput& in, Eigen::MatrixXd* out) {
  run(model, in, {in.weights}, {out});
}

Eigen::MatrixXd forwardBatch(const BodyModel& model, const BatchInput& in) {
  Eigen::MatrixXd out;
  forwardBatch(model, in, &out);
  return out;
}

}  // namespace smpl
