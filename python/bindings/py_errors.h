// Errors raised to Python: the CLI's one-line message ("Error loading
// walk.npz: ...", request/error_line.h) and its exit code (cli/exit_code.h),
// as smpl_export.Error (a ValueError) or its subclass for the code:
// UsageError 1, InputError 2, ExportError 3, OutputError 4. The classes are
// the Python shim's (smpl_export/__init__.py), handed over at import.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "core/result.h"

namespace smpl::py {

// Thrown by the bindings (with or without the GIL), turned into the shim's
// exception class for `exit_code` when it reaches Python.
struct Failure {
  std::string message;
  int exit_code = 3;
};

// The failure for a library error: the exit code of its kind (unclassified: 3).
Failure failureOf(const Error& error);
// A usage error (exit 1) with `message` as the line.
Failure usageFailure(const std::string& message);

// _set_error_classes({code: class}) and the translator of Failure.
void registerErrors(pybind11::module_& m);

}  // namespace smpl::py
