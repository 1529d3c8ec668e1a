// The forward pass for many poses of one subject at once, as matrix products:
// the pose correctives of a block of frames are one (3N x P)(P x T) GEMM and
// the skinning one (N x K)(K x 12) product per frame. Same math as forward()
// (tests compare them); for benchmarks and bulk evaluation. The corrective
// GEMM and the blend of the joint transforms run in single precision (twice
// the SIMD width, half the memory traffic of posedirs), the final transform
// in double (in float, widened, with the AVX-512 kernels), the result in
// double: together < 1e-6 m from forward(), about float32 file precision.
// The loops are core/math/forward_batch_kernels.h: AVX-512, AVX2 or
// portable kernels, the widest the CPU runs unless BatchInput::kernels says
// otherwise.
//
// Per frame of the 6890-vertex SMPL layout that is 6.35 M multiply-adds
// (dense weights); smpl-bench --compare prints ours against that count at
// the machine's measured multiply-add peak. Besides them, per frame: the
// kinematic chain and pose features (O(K), in double) and writing the 3N
// doubles of the result; per call: packing the weights and the rest mesh,
// and posedirs unless BatchInput::posedirs is given.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/body_model.h"
#include "core/math/forward.h"
#include "core/math/forward_batch_kernels.h"

namespace smpl {

struct BatchInput {
  const ShapedBody* body = nullptr;  // from shapeBody()
  const std::vector<Rotations>* frames = nullptr;
  const Eigen::MatrixXd* weights = nullptr;  // N x K override; null = model's
  int threads = 1;                           // worker threads over blocks of frames
  int block = 256;                           // frames per GEMM
  // Kernel set (forward_batch_kernels.h). Best: the widest the CPU runs.
  // A set the CPU lacks is never run: the request falls back to Best.
  Kernels kernels = Kernels::Best;
  // Optional: packPosedirs(model) made once for many calls on the same
  // (unchanged) model. Null: each call packs posedirs itself, which reads
  // all of them (34 MB for SMPL); one whose sizes do not match is ignored.
  const batch::PackedPosedirs* posedirs = nullptr;
};

// posedirs packed for the kernels (float panels), for BatchInput::posedirs,
// on `threads` workers (the same data for any count).
batch::PackedPosedirs packPosedirs(const BodyModel& model, int threads = 1);

// Returns 3N x T: column t holds frame t's vertices (x0 y0 z0 x1 ...).
Eigen::MatrixXd forwardBatch(const BodyModel& model, const BatchInput& input);

// The same into *out, resized to 3N x T only if its shape differs: repeated
// calls reuse its memory. A fresh result is first touched page by page:
// for 1024 SMPL frames (169 MB) the page faults cost about as much as the
// arithmetic on 4 KiB pages, a third of it on the huge pages asked for.
void forwardBatch(const BodyModel& model, const BatchInput& input, Eigen::MatrixXd* out);

// The same frames skinned with several weight matrices (each N x K; null =
// the model's; input.weights is ignored): one 3N x T result per matrix, in
// order. The pose correctives are computed once per block for all of them,
// so comparing S skins costs one corrective GEMM, not S (pruning_error).
std::vector<Eigen::MatrixXd> forwardBatchSkins(const BodyModel& model, const BatchInput& input,
                                               const std::vector<const Eigen::MatrixXd*>& skins);

}  // namespace smpl
