// What smpl-export prints after one export: on stderr the input notes (a
// --betas-file whose rows were averaged) and the export's notes (unless
// --quiet) and its warnings (always); on stdout (unless --quiet) the summary
// (counts, size, time; "skeleton only" for a format without a mesh, BVH; the
// animation frames, the skinning error of the chosen influences, the model
// file used); and the progress bar of a long bake.
#pragma once

#include <string>

#include "request/export_request.h"

namespace smpl {

// The summary on stdout (counts, size, time, frames, skinning error, model
// file); text from files and the command line goes through printable().
void printSummary(const std::string& out, const ExportReport& report);

// The report's notes on stderr, each "note: ..." (hidden by `quiet`), and its
// warnings, each "warning: ..." (always: the model used is not the one the
// motion asks for, a --model folder's fallback).
void printNotes(const ExportReport& report, bool quiet);

// A progress bar on stderr for the motion `name` baking (fraction in [0, 1];
// a newline at 1): "baking NAME [####    ]  45% ETA 0:03" (time left from the
// time so far), then the time taken at 100%. The request's progress callback
// on a terminal.
void drawProgress(const std::string& name, double fraction);

}  // namespace smpl
