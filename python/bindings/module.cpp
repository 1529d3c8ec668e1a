// The extension module _smpl_export behind the package smpl_export (its
// Python shim, python/smpl_export/__init__.py, is the documented API):
// the model and its forward pass, the motion readers and the exporter, on
// the library's export request.
#include <pybind11/pybind11.h>

#include "core/math/eigen_blocking.h"
#include "python/bindings/py_errors.h"
#include "python/bindings/py_export.h"
#include "python/bindings/py_model.h"
#include "python/bindings/py_motion.h"
#include "python/bindings/py_settings.h"

PYBIND11_MODULE(_smpl_export, m) {
  // The CLI's sums (core/math/eigen_blocking.h), so the bytes are the CLI's.
  smpl::useFixedEigenBlocking();
  m.attr("__version__") = SMPL_EXPORT_VERSION;
  smpl::py::registerErrors(m);
  smpl::py::registerModel(m);
  smpl::py::registerMotion(m);
  smpl::py::registerSettings(m);
  smpl::py::registerExport(m);
}
