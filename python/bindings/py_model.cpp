// PyModel, load_model, the Model class: see py_model.h.
#include "python/bindings/py_model.h"

#include <pybind11/stl.h>

#include "python/bindings/py_errors.h"
#include "python/bindings/py_forward.h"
#include "request/error_line.h"

namespace pyb = pybind11;
using namespace pybind11::literals;

namespace smpl::py {

PyModel loadModel(const std::string& path) {
  PyModel m;
  m.path = path;
  m.source = std::make_shared<ModelSource>(path);
  if (m.source->isFolder())
    throw usageFailure(errorLine("loading", path,
                                 "a folder: give one model file (a folder's pick needs a motion; "
                                 "export(..., model=FOLDER) is not supported)"));
  Result<ModelPick> pick = [&] {
    pyb::gil_scoped_release release;
    return m.source->forMotion(nullptr);
  }();
  if (!pick) throw Failure{errorLine("loading", path, pick.message()), 2};
  m.model = pick->model;
  return m;
}

void registerModel(pyb::module_& m) {
  pyb::class_<PyModel>(m, "Model", "A body model (SMPL, SMPL-H, SMPL-X, MANO) loaded once.")
      .def_readonly("path", &PyModel::path, "The file given to load_model, or 'builtin'.")
      .def_property_readonly(
          "family", [](const PyModel& p) { return std::string(modelKindName(p.model->kind)); },
          "'smpl', 'smplh', 'smplx' or 'mano'.")
      .def_property_readonly(
          "joint_names", [](const PyModel& p) { return p.model->joint_names; },
          "K joint names in model order.")
      .def_property_readonly(
          "parents", [](const PyModel& p) { return p.model->parents; },
          "K parent indices; parents[0] == -1.")
      .def_property_readonly(
          "num_betas", [](const PyModel& p) { return p.model->numBetas(); }, "B shape directions.")
      .def_property_readonly(
          "num_expression", [](const PyModel& p) { return p.model->numExpressions(); },
          "E expression directions (SMPL-X; 0 otherwise).")
      .def_property_readonly(
          "num_vertices", [](const PyModel& p) { return p.model->numVertices(); }, "V vertices.")
      .def_property_readonly(
          "num_joints", [](const PyModel& p) { return p.model->numJoints(); }, "K joints.")
      .def_property_readonly(
          "name", [](const PyModel& p) { return p.model->name; }, "The model file's name.")
      .def("_forward", &forwardModel, "betas"_a, "poses"_a, "trans"_a, "expression"_a, "dtype"_a);
  m.def("_load_model", &loadModel, "path"_a);
}

}  // namespace smpl::py
