// What smpl-export prints after one export (unless --quiet): the input notes
// (a --betas-file whose rows were averaged, a model folder's fallback), the
// summary line (counts, size, time; "skeleton only" for a format without a
// mesh), the animation frames, the export's notes,
// the skinning error of the chosen influences and the model file used; and
// the progress bar of a long bake.
#pragma once

#include <string>

#include "exporter/request/export_request.h"

namespace smpl {

// Prints to stdout; text from files and the command line goes through printable().
void printSummary(const std::string& out, const ExportReport& report);

// A progress bar on stderr for the motion `name` baking (fraction in [0, 1];
// a newline at 1): the request's progress callback on a terminal.
void drawProgress(const std::string& name, double fraction);

}  // namespace smpl
