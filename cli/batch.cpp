#include "cli/batch.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "cli/export_job.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> listMotions(const std::string& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".npz" || ext == ".json")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Up to date: output and sidecar exist and are newer than every input.
bool upToDate(const fs::path& out, const fs::path& motion, const std::string& model) {
  std::error_code ec;
  const fs::path sidecar = out.string() + ".smpl.json";
  if (!fs::exists(out, ec) || !fs::exists(sidecar, ec)) return false;
  auto built = std::min(fs::last_write_time(out, ec), fs::last_write_time(sidecar, ec));
  if (ec || built < fs::last_write_time(motion, ec)) return false;
  return model == "builtin" || built >= fs::last_write_time(model, ec);
}

}  // namespace

BatchSummary runBatch(ModelSource& models, const Settings& s) {
  BatchSummary summary;
  std::error_code ec;
  fs::create_directories(s.out_dir, ec);
  const std::vector<fs::path> motions = listMotions(s.motion_dir);
  if (motions.empty()) std::fprintf(stderr, "Warning: no .npz or .json motions in %s\n", s.motion_dir.c_str());
  std::atomic<size_t> next{0};
  std::mutex print;
  auto worker = [&] {
    for (size_t i; (i = next++) < motions.size();) {
      const fs::path out = fs::path(s.out_dir) / (motions[i].stem().string() + "." + s.format);
      if (upToDate(out, motions[i], s.model)) {
        std::lock_guard<std::mutex> lock(print);
        ++summary.skipped;
        continue;
      }
      JobFailure failure{kExitOk, ""};
      Result<ModelPick> pick = models.forMotion(motions[i].string());  // per motion: a folder picks by gender
      if (!pick) failure = JobFailure{kExitLoad, errorLine("loading", s.model, pick.message())};
      Result<ExportReport> r = !pick ? Result<ExportReport>(makeError(failure.message))
                                     : runExport(*pick->model, s, ExportJob{out.string(), {motions[i].string()}, false}, &failure);
      std::lock_guard<std::mutex> lock(print);
      if (!r) {
        ++summary.failed;
        std::fprintf(stderr, "%s\n", failure.message.c_str());
        continue;
      }
      ++summary.converted;
      if (!s.quiet)
        std::printf("%s: %d frames, %.2f MB, %.0f ms, model %s%s%s\n", out.c_str(), r->frames, r->bytes / 1e6,
                    r->seconds * 1e3, pick->path.c_str(), pick->note.empty() ? "" : "; note: ", pick->note.c_str());
    }
  };
  const unsigned threads = s.threads > 0 ? s.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<size_t>(threads, std::max<size_t>(1, motions.size())); ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  std::printf("batch: %d converted, %d up to date, %d failed\n", summary.converted, summary.skipped, summary.failed);
  return summary;
}

}  // namespace smpl
