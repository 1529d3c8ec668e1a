// What produced an output, as one hash recorded in its sidecar
// ("producer": {"hash": ...}, exporter/metadata_json.h). Batch mode rebuilds
// an output whose recorded hash differs from the one this run would record,
// so "up to date" means "same inputs and same options".
//
// The hash covers: a schema tag and the exporter version (SMPL_EXPORT_VERSION);
// the request's hashed_options (name and value as given, sorted): every
// option that changes the output's bytes (the command line's option table
// leaves out those that do not, cli/options.h Hashed::No: --threads,
// --quiet, --force, --out, ..., and those naming input files,
// Hashed::Content: --model, --motion, --betas-file, --uv, --dmpl), which
// enter by identity instead: the model's base name and
// content (or, for a model folder, each file a model could be picked from,
// two levels deep, by relative path, size and modification time; "builtin"
// for the demo body), the betas, UV and DMPL files' content, each motion's base name
// and size. A motion edited in place is caught by the batch's time check
// (output older than its motion), so motions are not read to hash them.
#pragma once

#include <string>
#include <vector>

#include "core/io/content_hash.h"
#include "core/result.h"
#include "request/export_request.h"

namespace smpl {

// The part shared by every output of a run: options, model, betas/UV files.
// Reads the model once (1 MB at a time). Error: the unreadable input file.
Result<ContentHash> producerBase(const ExportRequest& request);

// The hash of one output: `base` plus its motions' and --hands files' base
// names and sizes (a folder: each file's name and size).
std::string producerHash(ContentHash base, const std::vector<std::string>& motions,
                         const std::vector<std::string>& hands = {});

}  // namespace smpl
