// glTF writer stage: accessors over new bufferViews of buffer 0 (floats with
// bounds, integers, joint indices), row-major copies of Eigen matrices and the
// extension list (gltf_stages.h).
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

#include "writers/gltf/gltf_meshopt.h"
#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {
namespace {

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 1;
  }
}

}  // namespace

// Float accessor; bounds (per-component min/max) where glTF requires them.
int addFloats(GltfBuild& b, const float* values, size_t size, int type, int target, bool bounds,
              bool in_place) {
  const int n = componentCount(type);
  const size_t count = size / size_t(n);
  const int view = in_place ? addViewInPlace(b, values, size * sizeof(float), target)
                            : addView(b, values, size * sizeof(float), target);
  markMeshopt(b, view, MeshoptMode::Attributes, 4 * n);
  const int accessor = addAccessor(b, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, count);
  tinygltf::Accessor& a = b.model.accessors[size_t(accessor)];
  if (bounds && count > 0) floatBounds(values, count, n, &a.minValues, &a.maxValues);
  return accessor;
}

// Integer accessor; meshopt takes index lists (INDICES) and 4-byte-multiple elements.
template <class T>
int addIntegers(GltfBuild& b, const std::vector<T>& values, int component_type, int type,
                int target) {
  const int view = addView(b, values.data(), values.size() * sizeof(T), target);
  const int element = int(sizeof(T)) * componentCount(type);
  if (target == TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER)
    markMeshopt(b, view, MeshoptMode::Indices, int(sizeof(T)));
  else if (element % 4 == 0)
    markMeshopt(b, view, MeshoptMode::Attributes, element);
  return addAccessor(b, view, component_type, type, values.size() / size_t(componentCount(type)));
}

template int addIntegers<uint8_t>(GltfBuild&, const std::vector<uint8_t>&, int, int, int);
template int addIntegers<uint16_t>(GltfBuild&, const std::vector<uint16_t>&, int, int, int);
template int addIntegers<uint32_t>(GltfBuild&, const std::vector<uint32_t>&, int, int, int);

// JOINTS_n in the narrowest type that holds every joint index.
int addJoints(GltfBuild& b, const std::vector<uint16_t>& joints, bool wide) {
  if (!wide) {
    std::vector<uint8_t> narrow(joints.begin(), joints.end());
    return addIntegers(b, narrow, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4,
                       TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  return addIntegers(b, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4,
                     TINYGLTF_TARGET_ARRAY_BUFFER);
}

std::vector<float> rowMajor(const Eigen::MatrixXf& m) {
  std::vector<float> out(size_t(m.rows() * m.cols()));
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) out[size_t(r * m.cols() + c)] = m(r, c);
  return out;
}

void requireExtension(tinygltf::Model& model, const char* name) {
  for (const std::string& e : model.extensionsUsed)
    if (e == name) return;
  model.extensionsUsed.push_back(name);
  model.extensionsRequired.push_back(name);
}

}  // namespace gltf
}  // namespace smpl
