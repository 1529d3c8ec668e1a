#include "writers/gltf/gltf_buffer.h"

#include <algorithm>

namespace smpl {

namespace {

// A new view of `size` bytes at the (aligned) end of buffer 0.
int newView(GltfBuild& b, size_t size, int target, int stride) {
  b.bin.resize(align4(b.bin.size()), '\0');
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = b.bufferSize();
  view.byteLength = size;
  view.byteStride = size_t(stride);
  view.target = target;
  b.model.bufferViews.push_back(view);
  return int(b.model.bufferViews.size()) - 1;
}

}  // namespace

int addView(GltfBuild& b, const void* data, size_t size, int target, int stride) {
  const int view = newView(b, size, target, stride);
  b.bin.append(static_cast<const char*>(data), size);
  return view;
}

int addViewInPlace(GltfBuild& b, const void* data, size_t size, int target) {
  if (b.meshopt || size % 4 != 0) return addView(b, data, size, target);
  const int view = newView(b, size, target, 0);
  b.splices.push_back(Writer::Splice{b.bin.size(), ByteSpan{data, size}});
  b.spliced += size;
  return view;
}

int addAccessor(GltfBuild& b, int view, int component_type, int type, size_t count,
                bool normalized) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  accessor.normalized = normalized;
  b.model.accessors.push_back(std::move(accessor));
  return int(b.model.accessors.size()) - 1;
}

void floatBounds(const float* values, size_t count, int n, std::vector<double>* min,
                 std::vector<double>* max) {
  min->assign(size_t(n), 0.0);
  max->assign(size_t(n), 0.0);
  if (count == 0) return;
  // One pass over the tuples (a target's deltas are read once, not once per
  // component); min and max are exact, so the order does not matter.
  std::vector<float> lo(values, values + n), hi(values, values + n);
  for (size_t i = 1; i < count; ++i) {
    const float* t = values + i * size_t(n);
    for (int c = 0; c < n; ++c) {
      lo[size_t(c)] = std::min(lo[size_t(c)], t[c]);
      hi[size_t(c)] = std::max(hi[size_t(c)], t[c]);
    }
  }
  for (int c = 0; c < n; ++c) {
    (*min)[size_t(c)] = lo[size_t(c)];
    (*max)[size_t(c)] = hi[size_t(c)];
  }
}

}  // namespace smpl
