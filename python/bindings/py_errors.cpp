// Failure -> the shim's exception classes: see py_errors.h.
#include "python/bindings/py_errors.h"

#include "cli/exit_code.h"

namespace smpl::py {
namespace {

// code -> class, set once by the shim at import (the module lives until exit).
pybind11::dict* errorClasses() {
  static pybind11::dict* classes = new pybind11::dict();  // never destroyed: no GIL at exit
  return classes;
}

}  // namespace

Failure failureOf(const Error& error) { return Failure{error.message, exitCodeFor(error.kind)}; }

Failure usageFailure(const std::string& message) { return Failure{message, kExitUsage}; }

void registerErrors(pybind11::module_& m) {
  m.def(
      "_set_error_classes", [](pybind11::dict classes) { *errorClasses() = classes; },
      "Internal: the exception class for each exit code (the shim's).");
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Failure& f) {
      pybind11::dict& classes = *errorClasses();
      pybind11::int_ code(f.exit_code);
      if (!classes.contains(code)) {
        PyErr_SetString(PyExc_ValueError, f.message.c_str());
        return;
      }
      pybind11::object error = classes[code](f.message, f.exit_code);
      PyErr_SetObject(error.get_type().ptr(), error.ptr());
    }
  });
}

}  // namespace smpl::py
