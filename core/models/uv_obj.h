// UVs from a Wavefront OBJ that shares the model's vertex order (`--uv`), as
// the model authors ship them (e.g. smpl_uv.obj). A model vertex with several
// UVs (a seam) is split into several asset vertices; source_vertex maps each
// back, so skin weights and morph targets follow the split.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/models/uv_split.h"
#include "core/result.h"

namespace smpl {

// The OBJ's faces must reference only model vertices (1-based, < N) and each
// face a texture coordinate; polygons are fanned into triangles.
Result<UvLayout> loadUvLayout(const std::string& path, const BodyModel& model);

}  // namespace smpl
