// Internal to the glTF writer: the model under construction and its one binary
// buffer. The bytes live in `bin`, outside tinygltf, so the GLB's BIN chunk is
// written once from here instead of being copied through tinygltf's buffer,
// its output stream and the GLB splice (the writer's main cost before).
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <string>
#include <vector>

#include "writers/writer.h"

namespace smpl {

// EXT_meshopt_compression codecs (gltf_meshopt.h).
enum class MeshoptMode { Attributes, Indices };
enum class MeshoptFilter { None, Quaternion };

// One bufferView to compress with EXT_meshopt_compression (--meshopt).
struct MeshoptMark {
  int view = 0;
  MeshoptMode mode = MeshoptMode::Attributes;
  int element_size = 4;  // bytes per element (the extension's byteStride)
  MeshoptFilter filter = MeshoptFilter::None;
};

struct GltfBuild {
  tinygltf::Model model;
  // Buffer 0 is `bin` with `splices` inserted (Writer::Splice: the asset's own
  // arrays, not copied; `spliced` bytes in all, a multiple of 4); every
  // bufferView starts 4-byte aligned.
  std::string bin;
  std::vector<Writer::Splice> splices;
  size_t spliced = 0;
  bool meshopt = false;                    // --meshopt: views are marked as they are added
  std::vector<MeshoptMark> meshopt_marks;  // in view order
  size_t bufferSize() const { return bin.size() + spliced; }
};

inline size_t align4(size_t n) { return (n + 3) & ~size_t(3); }

// Appends `size` raw bytes as a new bufferView (target 0: none; stride 0: tight).
int addView(GltfBuild& b, const void* data, size_t size, int target, int stride = 0);

// The same view, its bytes left where they are: `data` must live until the
// file is written (the asset's arrays). Copied as addView does when meshopt
// re-encodes the views from `bin`, or when `size` is not a multiple of 4.
int addViewInPlace(GltfBuild& b, const void* data, size_t size, int target);

// A new accessor over `view` (-1: none, e.g. Draco or all-zero sparse base).
int addAccessor(GltfBuild& b, int view, int component_type, int type, size_t count,
                bool normalized = false);

// Per-component min/max of `count` float tuples of `n` components.
void floatBounds(const float* values, size_t count, int n, std::vector<double>* min,
                 std::vector<double>* max);

}  // namespace smpl
