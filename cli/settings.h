// Command-line settings of smpl-export: argv parsed into the export request
// (request/export_request.h) plus what only the command line has
// (batch mode, printing). Parsing checks syntax only (gltfpack's discipline:
// unknown options, malformed values and options used where they do not apply
// fail first); every range and every conflict between options is checked
// once, by the request (request/check_request.h). The options
// themselves are described once, in cli/options.h.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/result.h"
#include "request/export_request.h"
#include "writers/writer.h"

namespace smpl {

struct Settings {
  ExportRequest request;                 // every option of the export itself
  std::string out_dir;                   // --out-dir DIR (batch mode)
  bool force = false;                    // --force (batch): rebuild outputs even when up to date
  int shard_index = 0, shard_count = 1;  // --shard I/N (batch): this run's share
  bool quiet = false;                    // --quiet, -q: no summary
  bool help = false;
  bool version = false;
  std::string preset;  // --preset web|engine|archive (cli/presets.h), applied after parsing
  // (name, value) of every option as given, in order (aliases as their option).
  std::vector<std::pair<std::string, std::string>> given_options;
};

// Batch mode: --motion-dir or --out-dir given.
bool isBatch(const Settings& settings);

// The writer row (writers/writer.h) of the run's outputs: batch mode's
// --format (default the table's first row), else --out's extension; null when
// --out has none the table knows (the request reports it).
const WriterFormat* outputFormat(const Settings& settings);

// Parse argv through the option table, then the rules of where options apply
// (the table's Applies column) and batch mode's pair of folders; fills
// request.hashed_options from the table's Hashed column. Errors are one line
// for the user, of kind Usage (exit 1).
Result<Settings> parseSettings(int argc, const char* const* argv);

}  // namespace smpl
