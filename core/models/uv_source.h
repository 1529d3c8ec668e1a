// Which UVs an export gets (`--uv`): the model file's own `vt`/`ft` when it
// ships them (SMPL-X release) and no --uv is given; --uv FILE.obj or
// --uv <stem>_uv.npy|<stem>_ft.npy overrides them; --uv none turns UVs off.
// Every source splits seams the same way (uv_split.h).
#pragma once

#include <optional>
#include <string>

#include "core/body_model.h"
#include "core/models/uv_split.h"
#include "core/result.h"

namespace smpl {

// `option`: "" (model UVs if any), "none", an .obj path or a numpy pair path.
// An empty optional means "no UVs".
Result<std::optional<UvLayout>> resolveUvLayout(const std::string& option, const BodyModel& model);

// The model's own UVs (model.texcoords/texcoord_faces), split at seams; nullopt if it has none.
Result<std::optional<UvLayout>> modelUvLayout(const BodyModel& model);

}  // namespace smpl
