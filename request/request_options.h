// The request holds the options of the stages below it as they are
// (ExportRequest::asset, ::animation, ::writer); these add what only the run
// knows: the resolved betas, whether the output's writer has a mesh, binary
// or not, and the external buffer's name. The values were checked by
// check_request.h.
#pragma once

#include <string>
#include <vector>

#include "exporter/animation.h"
#include "exporter/export_options.h"
#include "request/export_request.h"
#include "writers/writer.h"

namespace smpl {

// The export's worker threads (0: all cores): the request's own count (a
// batch job writes on one thread but fits on all), else --threads.
int exportThreads(const ExportRequest& request);

// `betas`: the run's (RunInputs, run_request.h); the encoding stays as asked
// (Auto is resolved by exportAsset, export_asset.h); no mesh when the
// output's writer row has none (writers/writer.h needs_mesh).
ExportOptions exportOptionsOf(const ExportRequest& request, const std::vector<double>& betas);

// For writing request.out; `buffer_path`: its external buffer (run_paths.h
// gltfBufferPath), "" = none.
WriterOptions writerOptionsOf(const ExportRequest& request, const std::string& buffer_path);

}  // namespace smpl
