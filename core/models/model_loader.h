// Model files -> BodyModel. Chooses the reader by content (zip magic -> npz,
// pickle PROTO/opcode -> pkl), then validates every array against N and K:
//   "model.pkl: 'posedirs' has shape (6890,3,200); expected (6890,3,207)".
// The family comes from the joint count (SMPL 24, SMPL-H 52, SMPL-X 55,
// MANO 16). SMPL-X stores 300 shape + 100 expression columns in one
// `shapedirs`; the split is made here (first min(B,300) shape columns; the
// rest are expression), unless the file has a separate `exprdirs`.
#pragma once

#include <string>

#include "core/array.h"
#include "core/body_model.h"
#include "core/result.h"

namespace smpl {

Result<BodyModel> loadModel(const std::string& path);

// Build and validate from arrays already loaded; `context` names the source.
Result<BodyModel> buildModel(const ArrayDict& arrays, const std::string& context);

// Checks the invariants documented in body_model.h (also run on the demo body).
Status validateModel(const BodyModel& model, const std::string& context);

}  // namespace smpl
