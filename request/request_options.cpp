#include "request/request_options.h"

#include "core/io/file_io.h"

namespace smpl {

int exportThreads(const ExportRequest& r) {
  return r.asset.threads > 0 ? r.asset.threads : r.writer.threads.value_or(0);
}

ExportOptions exportOptionsOf(const ExportRequest& r, const std::vector<double>& betas) {
  ExportOptions o = r.asset;
  o.betas = betas;
  o.threads = exportThreads(r);  // --threads: the fit and refit too
  const WriterFormat* format = writerFormatForPath(r.out);
  o.mesh = !format || format->needs_mesh;  // a skeleton-only writer: no skin, no morph targets
  return o;
}

WriterOptions writerOptionsOf(const ExportRequest& r, const std::string& buffer_path) {
  WriterOptions w = r.writer;
  const WriterFormat* format = writerFormatForPath(r.out);
  w.binary = !format || format->binary;
  w.buffer_uri = buffer_path.empty() ? "" : baseName(buffer_path);
  return w;
}

}  // namespace smpl
