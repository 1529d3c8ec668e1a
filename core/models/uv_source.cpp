#include "core/models/uv_source.h"

#include "core/io/file_io.h"
#include "core/models/uv_npy.h"
#include "core/models/uv_obj.h"

namespace smpl {

Result<std::optional<UvLayout>> modelUvLayout(const BodyModel& model) {
  if (model.texcoord_faces.rows() == 0) return std::optional<UvLayout>();
  Result<UvLayout> layout = splitUvSeams(model.faces, model.texcoord_faces, model.texcoords,
                                         model.numVertices(), model.name + ": 'ft'");
  if (!layout) return layout.error();
  return std::optional<UvLayout>(std::move(*layout));
}

Result<std::optional<UvLayout>> resolveUvLayout(const std::string& option, const BodyModel& model) {
  if (option == "none") return std::optional<UvLayout>();
  if (option.empty()) return modelUvLayout(model);
  Result<UvLayout> layout =
      hasSuffix(option, ".npy") ? loadUvNumpyPair(option, model) : loadUvLayout(option, model);
  if (!layout) return layout.error();
  return std::optional<UvLayout>(std::move(*layout));
}

}  // namespace smpl
