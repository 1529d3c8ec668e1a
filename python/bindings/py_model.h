// smpl_export.Model: a body model loaded once (any model file the CLI reads,
// or "builtin"), its facts, and its forward pass on arrays. The model is held
// by a ModelSource (request/model_source.h) that the exports of the model
// share, so an export never reads the model file again.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "core/body_model.h"
#include "request/model_source.h"

namespace smpl::py {

struct PyModel {
  std::string path;                     // as given to load_model ("builtin" for the demo body)
  std::shared_ptr<ModelSource> source;  // holds the loaded model
  const BodyModel* model = nullptr;     // owned by `source`
};

// load_model(path): Failure (input, exit 2) "Error loading <path>: ...".
PyModel loadModel(const std::string& path);

// Model class, load_model().
void registerModel(pybind11::module_& m);

}  // namespace smpl::py
