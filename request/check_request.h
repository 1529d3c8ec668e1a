// Every check of an export request's values, in one place:
// each option's range and each conflict between options is checked here and
// nowhere else. The command line only parses (cli/settings.cpp: syntax, and
// where an option applies); the library functions below the request keep at
// most documented preconditions (clamps), never a second user-facing check.
//
// Two stages, each as early as its information allows:
//   checkRequest          before any file is read: ranges that need no input
//                         (--fps, --threads, ...) and conflicts between options;
//   checkRequestForModel  right after the model is known (the model file, or a
//                         folder's pick for the first motion): counts against
//                         the model (--max-influences 1..K, betas, ...);
//   checkDmplCount        right after the DMPL basis is read.
// Messages name the option as the user typed it ("--max-influences must be
// between 1 and 24 (the model's joints) or 'all', got 30"); errors are of
// kind Usage (exit 1) and carry no "Error in arguments: " prefix (the caller
// adds it, run_request.h).
#pragma once

#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/result.h"
#include "request/export_request.h"
#include "writers/writer.h"

namespace smpl {

// Ranges and conflicts that need no file, first failure wins: the ranges
//   --betas / --expression values |v| <= 1000 (core/models/validate_inputs.h),
//   --source-fps [1, 1000], --fps (0, 1000], --frames A >= 0 and B > A,
//   --corrective-epsilon [0, 0.01] m, --fbx-compress-level 0..12, --threads
//   1..1024, --dmpl-count >= 1; then --model given; the --betas /
//   --betas-file / --betas-from-motion conflicts; --dmpl-count and
//   --dmpl-joints regressed need --dmpl; --corrective-basis K >= 1 needs
//   correctives and signed or unit weights; --corrective-weights,
//   --quantize-morphs and --corrective-epsilon M > 0 need morph targets.
// For callers that write no asset (tools/reference).
Status checkRequestOptions(const ExportRequest& request);

// checkRequestOptions, then the output: --out given unless batch
// (motion_dir), its format (batch: --format) has a row in the writer table
// (writers/writer.h),
// and a format without a mesh gets no mesh options (--dmpl, --shape-keys,
// --expression-keys, --uv, --corrective-basis, --quantize-morphs).
Status checkRequest(const ExportRequest& request);

// A batch's writer row: --format (request.format), "" = the table's first;
// null when the table has no such row.
const WriterFormat* batchFormat(const ExportRequest& request);

// Counts against `model`: `betas` (the request's, from --betas or
// --betas-file) at most B values, --expression at most E, --max-influences
// 1..K (unless all), --shape-keys 0..B, --expression-keys 0..E,
// --corrective-basis 0..P.
Status checkRequestForModel(const ExportRequest& request, const std::vector<double>& betas,
                            const BodyModel& model);

// --dmpl-count against the `directions` D of the DMPL basis just read.
// Unlike the others this is a load error (kind Load, exit 2; the caller names
// the basis file): "--dmpl-count 9: the basis has 8 directions".
Status checkDmplCount(const ExportRequest& request, int directions);

}  // namespace smpl
