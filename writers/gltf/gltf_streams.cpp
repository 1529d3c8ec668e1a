// glTF writer stage: the mesh as the flat streams glTF stores (row-major
// positions, unit normals, v-flipped UVs, 4-slot JOINTS_n/WEIGHTS_n sets that
// pass the validator's sum check, the triangle list) (gltf_stages.h).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {
namespace {

// Unit length in float (the validator checks it); a zero normal, which only
// an unreferenced or degenerate vertex has, becomes +Y rather than invalid.
std::vector<float> unitNormals(const Eigen::MatrixXf& normals) {
  std::vector<float> out = rowMajor(normals);
  for (size_t i = 0; i < out.size(); i += 3) {
    double len = std::sqrt(double(out[i]) * out[i] + double(out[i + 1]) * out[i + 1] +
                           double(out[i + 2]) * out[i + 2]);
    for (int c = 0; c < 3; ++c)
      out[i + c] = len > 0 ? float(out[i + c] / len) : (c == 1 ? 1.f : 0.f);
  }
  return out;
}

std::vector<float> flippedUvs(const Eigen::MatrixXf& uvs) {
  std::vector<float> out = rowMajor(uvs);
  for (size_t i = 1; i < out.size(); i += 2) out[i] = 1.0f - out[i];
  return out;
}

// The validator's weight sum: float32 accumulation over component c of every
// set in turn (WEIGHTS_0[c], WEIGHTS_1[c], ...), tolerance 2e-7 per nonzero.
bool validatorNormalised(const std::vector<float>& w, int sets) {
  float sum = 0.f;
  int nonzero = 0;
  for (int c = 0; c < 4; ++c)
    for (int s = 0; s < sets; ++s)
      if (w[size_t(4 * s + c)] != 0.f) {
        sum = float(sum + w[size_t(4 * s + c)]);
        ++nonzero;
      }
  return std::fabs(double(sum) - 1.0) <= 2e-7 * nonzero;
}

// One vertex's influences in 4*sets slots: duplicates merged, zero-weight
// slots on joint 0 (the validator warns on a nonzero joint with zero weight),
// renormalised in float until the validator's sum check passes.
Status packVertexSkin(const SkinnedMesh& m, Eigen::Index v, int num_joints, int sets,
                      std::vector<uint16_t>& joints, std::vector<float>& weights) {
  const int slots = 4 * sets;
  std::vector<double> w(size_t(slots), 0.0);
  joints.assign(size_t(slots), 0);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < m.joints.cols(); ++i) {
    const int j = m.joints(v, i);
    const double wi = m.weights(v, i);
    if (!std::isfinite(wi) || wi < 0)
      return makeError("glTF writer: vertex " + std::to_string(v) + " has invalid skin weight");
    if (j < 0 || j >= num_joints)
      return makeError("glTF writer: vertex " + std::to_string(v) + " uses joint " +
                       std::to_string(j) + "; the skeleton has " + std::to_string(num_joints));
    if (wi == 0) continue;
    int slot = int(i);
    for (int k = 0; k < int(i); ++k)
      if (w[size_t(k)] > 0 && joints[size_t(k)] == j) slot = k;
    joints[size_t(slot)] = uint16_t(j);
    w[size_t(slot)] += wi;
    sum += wi;
  }
  if (!(sum > 0))
    return makeError("glTF writer: vertex " + std::to_string(v) + " has no positive skin weight");
  weights.assign(size_t(slots), 0.f);
  int largest = 0;
  for (int k = 0; k < slots; ++k) {
    weights[size_t(k)] = float(w[size_t(k)] / sum);
    if (w[size_t(k)] > w[size_t(largest)]) largest = k;
  }
  for (int round = 0; round < 4 && !validatorNormalised(weights, sets); ++round) {
    double total = 0.0;
    for (int c = 0; c < 4; ++c)
      for (int s = 0; s < sets; ++s) total = float(total + weights[size_t(4 * s + c)]);
    weights[size_t(largest)] = float(weights[size_t(largest)] + (1.0 - total));
  }
  return Status::success();
}

// JOINTS_n / WEIGHTS_n streams, ceil(M/4) sets.
Status packSkin(const SkinnedMesh& m, int num_joints, MeshStreams* out) {
  const int sets = int((m.joints.cols() + 3) / 4);
  const size_t v_count = size_t(m.positions.rows());
  out->joints.assign(size_t(sets), std::vector<uint16_t>(4 * v_count));
  out->weights.assign(size_t(sets), std::vector<float>(4 * v_count));
  out->wide_joints = num_joints >= 256;
  std::vector<uint16_t> vj;
  std::vector<float> vw;
  for (size_t v = 0; v < v_count; ++v) {
    Status st = packVertexSkin(m, Eigen::Index(v), num_joints, sets, vj, vw);
    if (!st) return st;
    for (int s = 0; s < sets; ++s)
      for (int c = 0; c < 4; ++c) {
        out->joints[size_t(s)][4 * v + size_t(c)] = vj[size_t(4 * s + c)];
        out->weights[size_t(s)][4 * v + size_t(c)] = vw[size_t(4 * s + c)];
      }
  }
  return Status::success();
}

}  // namespace

Result<MeshStreams> meshStreams(const SkinnedMesh& m, int num_joints) {
  MeshStreams out;
  out.vertices = size_t(m.positions.rows());
  out.positions = rowMajor(m.positions);
  out.normals = unitNormals(m.normals);
  if (m.uvs.rows() > 0) out.uvs = flippedUvs(m.uvs);
  Status st = packSkin(m, num_joints, &out);
  if (!st) return st.error();
  out.indices.reserve(size_t(m.triangles.size()));
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c) out.indices.push_back(uint32_t(m.triangles(f, c)));
  return out;
}

// 65535 is the primitive restart value of UNSIGNED_SHORT, so it must not occur.
bool wideIndices(size_t v_count) { return v_count >= 65535; }

}  // namespace gltf
}  // namespace smpl
