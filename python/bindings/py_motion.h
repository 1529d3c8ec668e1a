// smpl_export.Motion: one track of a motion, read once (a file of any layout
// the CLI reads, or a dict of arrays), with the reading options it was made
// with, so export() bakes exactly what was read.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/motions/motion.h"
#include "python/bindings/py_model.h"

namespace smpl::py {

struct PyMotion {
  std::shared_ptr<const Motion> motion;  // as decoded; fit hands resolved when a model was given
  std::string source;                    // the file, or the dict's name (the clip name)
  std::vector<std::string> reading;      // the reading options, as CLI arguments
  std::optional<PyModel> model;          // the model its rotations are mapped to
  std::vector<std::string> joint_names;  // K: the model's, else the motion layout's
  std::vector<double> rotations;         // T x K x 3 x 3, local to each parent
};

// Motion class, _read_motion(value, name, reading, model): `value` a path (str)
// or a dict; `reading` the reading options as CLI arguments.
void registerMotion(pybind11::module_& m);

}  // namespace smpl::py
