// smpl-export: a thin main. Parse argv into the export request (cli/settings.h),
// run it (request/run_request.h: checks, path guard, load, build,
// write) or a batch of them (cli/batch.h), print a summary. Everything the run
// reads or builds is charged to one memory budget (core/memory_budget.h, set
// by --memory-limit); the request turns exceptions that still escape into one
// error line with the exit code of the stage that failed, and the command
// line (cli/command_line.h) catches what escapes anywhere else as a last
// resort, never an abort.

#include "cli/command_line.h"
#include "cli/docs_folder.h"
#include "core/docs_location.h"
#include "core/math/eigen_blocking.h"
#include "core/os/system.h"

int main(int argc, char** argv) {
  smpl::useFixedEigenBlocking();  // the same sums on every machine (core/math/eigen_blocking.h)
  smpl::os::prepareStandardStreams();
  smpl::os::ignoreWriteSignals();  // a full disk quota or closed pipe is a write error (exit 4)
  smpl::os::Utf8Arguments args(argc, argv);
  // Messages that point at a page name the copy installed with this binary.
  smpl::setDocsFolder(smpl::findDocsFolder(smpl::os::executablePath()));
  return smpl::runCommandLine(args.argc(), args.argv());
}
