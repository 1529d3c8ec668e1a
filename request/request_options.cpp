#include "request/request_options.h"

#include "core/io/file_io.h"

namespace smpl {

ExportOptions exportOptionsOf(const ExportRequest& r, const std::vector<double>& betas) {
  ExportOptions o = r.asset;
  o.betas = betas;
  // --threads: the fit and refit too, unless the request set their count (a
  // batch job writes on one thread but fits on all)
  if (o.threads == 0) o.threads = r.writer.threads.value_or(0);
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
