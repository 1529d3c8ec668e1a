// smpl_export.export on the request layer: the CLI's parsed request run in
// process (request/run_request.h), the output kept in memory
// (exportToMemory: the bytes the CLI writes) or written as the CLI writes
// it (output and sidecar committed together), with the GIL released.
#pragma once

#include <pybind11/pybind11.h>

namespace smpl::py {

// _export(args, model, motion, memory) -> (bytes or the output path, notes):
// `args` the CLI arguments the shim built (--model, --out, --motion, options).
void registerExport(pybind11::module_& m);

}  // namespace smpl::py
