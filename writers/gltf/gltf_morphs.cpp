#include "writers/gltf/gltf_morphs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "writers/gltf/gltf_meshopt.h"

namespace smpl {
namespace {

int16_t quantize(float d) {
  const double q = std::nearbyint(double(d) * 32767.0);
  return int16_t(std::max(-32767.0, std::min(32767.0, q)));
}

// Integer bounds of the SHORT values, widened by the zeros sparse storage leaves.
void shortBounds(const std::vector<int16_t>& q, size_t stride, bool with_zero,
                 tinygltf::Accessor* a) {
  a->minValues.assign(3, with_zero || q.empty() ? 0.0 : 32767.0);
  a->maxValues.assign(3, with_zero || q.empty() ? 0.0 : -32767.0);
  for (size_t i = 0; i + 2 < q.size(); i += stride)
    for (size_t c = 0; c < 3; ++c) {
      a->minValues[c] = std::min(a->minValues[c], double(q[i + c]));
      a->maxValues[c] = std::max(a->maxValues[c], double(q[i + c]));
    }
}

void widenToZero(tinygltf::Accessor* a) {
  for (double& v : a->minValues) v = std::min(v, 0.0);
  for (double& v : a->maxValues) v = std::max(v, 0.0);
}

int addDense(GltfBuild& b, const MorphDeltas& d, const MorphEncoding& e) {
  const size_t v_count = size_t(d.rows());
  int accessor;
  if (e.quantized) {
    std::vector<int16_t> q(4 * v_count, 0);  // stride 8: vertex attributes are 4-byte aligned
    for (size_t v = 0; v < v_count; ++v)
      for (int c = 0; c < 3; ++c) q[4 * v + size_t(c)] = quantize(d(Eigen::Index(v), c));
    const int view = addView(b, q.data(), q.size() * 2, TINYGLTF_TARGET_ARRAY_BUFFER, 8);
    markMeshopt(b, view, MeshoptMode::Attributes, 8);
    accessor =
        addAccessor(b, view, TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC3, v_count, true);
    shortBounds(q, 4, false, &b.model.accessors[size_t(accessor)]);
  } else {
    // The asset's deltas, written where they are (MorphDeltas is glTF's layout).
    const int view = addViewInPlace(b, d.data(), 12 * v_count, TINYGLTF_TARGET_ARRAY_BUFFER);
    markMeshopt(b, view, MeshoptMode::Attributes, 12);
    accessor = addAccessor(b, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v_count);
    tinygltf::Accessor& a = b.model.accessors[size_t(accessor)];
    floatBounds(d.data(), v_count, 3, &a.minValues, &a.maxValues);
  }
  return accessor;
}

template <class Index>
int addSparseIndices(GltfBuild& b, const std::vector<uint32_t>& kept) {
  std::vector<Index> idx(kept.begin(), kept.end());
  return addView(b, idx.data(), idx.size() * sizeof(Index), 0);
}

int addSparse(GltfBuild& b, const MorphDeltas& d, const MorphEncoding& e) {
  const size_t v_count = size_t(d.rows());
  std::vector<uint32_t> kept;
  for (size_t v = 0; v < v_count; ++v) {
    const Eigen::Index r = Eigen::Index(v);
    const double len2 =
        double(d(r, 0)) * d(r, 0) + double(d(r, 1)) * d(r, 1) + double(d(r, 2)) * d(r, 2);
    if (len2 * e.peak * e.peak > e.epsilon * e.epsilon) kept.push_back(uint32_t(v));
  }
  // Sparse only where it is smaller than dense; dense keeps every delta exactly.
  const size_t value_bytes = e.quantized ? 6 : 12, dense_bytes = e.quantized ? 8 : 12;
  const bool wide = v_count > 65535;
  if (kept.size() * (value_bytes + (wide ? 4 : 2)) >= v_count * dense_bytes) return -1;
  // sparse.count must be >= 1, and loaders such as tinygltf reject an accessor
  // with neither bufferView nor sparse: keep vertex 0 when nothing else is kept.
  if (kept.empty()) kept.push_back(0);
  const int type = e.quantized ? TINYGLTF_COMPONENT_TYPE_SHORT : TINYGLTF_COMPONENT_TYPE_FLOAT;
  const int accessor = addAccessor(b, -1, type, TINYGLTF_TYPE_VEC3, v_count, e.quantized);
  const int index_type =
      wide ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const int index_view =
      wide ? addSparseIndices<uint32_t>(b, kept) : addSparseIndices<uint16_t>(b, kept);
  int value_view;
  tinygltf::Accessor bounds;
  if (e.quantized) {
    std::vector<int16_t> q(3 * kept.size());
    for (size_t i = 0; i < kept.size(); ++i)
      for (int c = 0; c < 3; ++c) q[3 * i + size_t(c)] = quantize(d(Eigen::Index(kept[i]), c));
    value_view = addView(b, q.data(), q.size() * 2, 0);
    shortBounds(q, 3, kept.size() < v_count, &bounds);
  } else {
    std::vector<float> f(3 * kept.size());
    for (size_t i = 0; i < kept.size(); ++i)
      for (int c = 0; c < 3; ++c) f[3 * i + size_t(c)] = d(Eigen::Index(kept[i]), c);
    value_view = addView(b, f.data(), f.size() * 4, 0);
    markMeshopt(b, value_view, MeshoptMode::Attributes, 12);  // (int16 triples, 6 bytes: not)
    floatBounds(f.data(), kept.size(), 3, &bounds.minValues, &bounds.maxValues);
    if (kept.size() < v_count) widenToZero(&bounds);
  }
  tinygltf::Accessor& a = b.model.accessors[size_t(accessor)];
  a.minValues = bounds.minValues;
  a.maxValues = bounds.maxValues;
  a.sparse.isSparse = true;
  a.sparse.count = int(kept.size());
  a.sparse.indices.bufferView = index_view;
  a.sparse.indices.byteOffset = 0;
  a.sparse.indices.componentType = index_type;
  a.sparse.values.bufferView = value_view;
  a.sparse.values.byteOffset = 0;
  return accessor;
}

}  // namespace

int addMorphTarget(GltfBuild& b, const MorphDeltas& deltas, const MorphEncoding& encoding) {
  const int sparse = encoding.epsilon > 0 ? addSparse(b, deltas, encoding) : -1;
  return sparse >= 0 ? sparse : addDense(b, deltas, encoding);
}

}  // namespace smpl
