// The request's fields as the options of the library stages below it: the
// asset (ExportOptions, exporter/export_options.h), the bake (AnimationOptions,
// exporter/animation.h) and the writer (WriterOptions, writers/writer.h).
// Pure translations: the values were checked by check_request.h.
#pragma once

#include <string>
#include <vector>

#include "exporter/animation.h"
#include "exporter/export_options.h"
#include "request/export_request.h"
#include "writers/writer.h"

namespace smpl {

// `betas`: the run's (RunInputs, run_request.h); the encoding stays as asked
// (Auto is resolved by exportAsset, export_asset.h); no mesh when the
// output's writer row has none (writers/writer.h needs_mesh).
ExportOptions exportOptionsOf(const ExportRequest& request, const std::vector<double>& betas);

AnimationOptions animationOptionsOf(const ExportRequest& request);

// For writing request.out; `buffer_path`: its external buffer (run_paths.h
// gltfBufferPath), "" = none.
WriterOptions writerOptionsOf(const ExportRequest& request, const std::string& buffer_path);

}  // namespace smpl
