// The smpl-export command line as a function: argv parsed into the export
// request (cli/settings.h), run (request/run_request.h) or run as a batch
// (cli/batch.h), the summary printed; what escapes becomes one error line
// with the exit code of the stage that failed, never an abort. main.cpp
// calls it once; the Python module's smpl_export.cli() calls it in process.
#pragma once

namespace smpl {

// argv[0] is the program name. Returns the exit code (cli/exit_code.h:
// 0 ok, 1 usage, 2 load, 3 export, 4 save); errors are printed to stderr,
// the summary to stdout (flushed: a failed write is exit 4). The caller sets
// the process up first (useFixedEigenBlocking, standard streams, UTF-8 argv).
int runCommandLine(int argc, char** argv);

}  // namespace smpl
