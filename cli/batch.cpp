#include "cli/batch.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "cli/batch_plan.h"
#include "cli/export_job.h"

namespace smpl {
namespace fs = std::filesystem;

BatchSummary runBatch(ModelSource& models, const Settings& s, const BatchPlan& plan) {
  BatchSummary summary;
  std::error_code ec;
  fs::create_directories(s.out_dir, ec);
  for (const std::string& note : plan.notes) std::printf("note: %s\n", note.c_str());
  for (const std::string& error : plan.errors) std::fprintf(stderr, "%s\n", error.c_str());
  summary.failed = static_cast<int>(plan.errors.size());
  const std::vector<PlannedOutput>& motions = plan.outputs;
  if (motions.empty()) std::fprintf(stderr, "Warning: no .npz or .json motions in %s\n", s.motion_dir.c_str());
  std::atomic<size_t> next{0};
  std::mutex print;
  auto worker = [&] {
    for (size_t i; (i = next++) < motions.size();) {
      const std::string& out = motions[i].out;
      if (motions[i].up_to_date) {
        std::lock_guard<std::mutex> lock(print);
        ++summary.skipped;
        continue;
      }
      JobFailure failure{kExitOk, ""};
      Result<ModelPick> pick = models.forMotion(motions[i].motion);  // per motion: a folder picks by gender
      if (!pick) failure = JobFailure{kExitLoad, errorLine("loading", s.model, pick.message())};
      const ExportJob job{out, {motions[i].motion}, false, motions[i].producer_hash};
      Result<ExportReport> r = !pick ? Result<ExportReport>(makeError(failure.message))
                                     : runExport(*pick->model, s, job, &failure);
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
