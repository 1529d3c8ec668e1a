// Seam splitting shared by every UV source (--uv OBJ, --uv *_uv.npy/*_ft.npy,
// `vt`/`ft` inside the model file): each distinct (model vertex, UV index)
// pair of the faces' corners becomes one asset vertex, numbered in order of
// first use, so a vertex on a seam is split and source_vertex maps it back
// (skin weights and morph targets follow the split).
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "core/body_model.h"
#include "core/result.h"

namespace smpl {

struct UvLayout {
  std::vector<int> source_vertex;  // V: model vertex of each asset vertex
  Eigen::MatrixXf uvs;             // V x 2 (OBJ convention, v up)
  Eigen::MatrixXi triangles;       // F x 3 asset-vertex indices
};

// A polygon's corners as (model vertex, uv index), 0-based.
using UvPolygon = std::vector<std::pair<int, int>>;

// Polygons are fanned into triangles. Errors name `context` and the first
// corner whose vertex (>= N) or uv index (>= uvs.size()) is out of range.
Result<UvLayout> splitUvSeams(const std::vector<UvPolygon>& polygons,
                              const std::vector<Eigen::Vector2f>& uvs, int num_vertices,
                              const std::string& context);

// Triangles as the model stores them (`faces` F x 3) with per-corner UV
// indices `uv_faces` (F x 3) into `uvs` (U x 2): the SMPL-X release's f/ft/vt.
Result<UvLayout> splitUvSeams(const Eigen::MatrixXi& faces, const Eigen::MatrixXi& uv_faces,
                              const Eigen::MatrixXd& uvs, int num_vertices,
                              const std::string& context);

}  // namespace smpl
