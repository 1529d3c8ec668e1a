#include "cli/batch.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

#include "cli/batch_plan.h"
#include "cli/batch_report.h"
#include "cli/manifest.h"
#include "cli/sha256.h"
#include "core/motions/motion.h"
#include "core/motions/motion_layout.h"
#include "core/os/path.h"
#include "core/os/system.h"
#include "core/parallel.h"
#include "core/stopwatch.h"
#include "request/error_line.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

// Output size and digest for the manifest (only when one is written).
void describeOutput(const std::string& out, bool manifest, ManifestEntry* e) {
  e->output = out;
  std::error_code ec;
  e->bytes = static_cast<size_t>(fs::file_size(os::fsPath(out), ec));
  if (Result<std::string> digest = manifest ? sha256File(out) : Result<std::string>(std::string());
      digest)
    e->sha256 = *digest;
}

// No pose keys at all (AMASS shape.npz, *_stagei.npz): skipped, not failed.
// An unreadable file (or one too large to read here) is left to the export,
// which reports it with its guards.
bool noPoseData(const std::string& motion) {
  try {
    Result<bool> poses = hasPoseData(motion);
    return poses && !*poses;
  } catch (const std::exception&) {
    return false;
  }
}

// ".npz, .smpl, .pkl or .json": the reader table's motion extensions.
std::string extensionList() {
  const std::vector<std::string> ext = motionFileExtensions();
  std::string text;
  for (size_t i = 0; i < ext.size(); ++i)
    text += (i == 0 ? "" : i + 1 == ext.size() ? " or " : ", ") + ext[i];
  return text;
}

void printHeader(const Settings& s, const BatchPlan& plan) {
  if (!s.quiet)
    for (const std::string& note : plan.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
  for (const std::string& error : plan.errors) std::fprintf(stderr, "%s\n", error.c_str());
  if (plan.listed == 0)
    std::fprintf(stderr, "warning: no motions (%s) in %s\n", extensionList().c_str(),
                 s.request.motion_dir.c_str());
  else if (plan.outputs.empty() && !s.quiet)
    std::fprintf(stderr, "note: shard %d/%d of the %zu motions in %s is empty\n", s.shard_index,
                 s.shard_count, plan.listed, s.request.motion_dir.c_str());
}

// After the batch: each distinct note once (stderr; a note many motions share
// with its count), unless quiet; warnings (a folder's model fallback) always.
void printFolded(const BatchNotes& notes, const BatchNotes& warnings, bool quiet) {
  for (const std::string& w : warnings.folded()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (quiet) return;
  for (const std::string& n : notes.folded()) std::fprintf(stderr, "note: %s\n", n.c_str());
}

// The request of one planned output: its motion, output and recorded hash;
// its stale temporaries were removed by planBatch.
ExportRequest jobRequest(const ExportRequest& base, const PlannedOutput& p, bool one_thread) {
  ExportRequest job = base;
  job.out = p.out;
  job.motions = {p.motion};
  job.producer_hash = p.producer_hash;
  job.clean_temporaries = false;
  if (one_thread) {
    // A subject's fit runs once while the jobs that need it wait: on every core.
    job.asset.threads = base.writer.threads.value_or(0);
    job.writer.threads = 1;
  }
  return job;
}

}  // namespace

BatchSummary runBatch(ModelSource& models, const Settings& s, const BatchPlan& plan,
                      const RunInputs& inputs) {
  BatchSummary summary;
  std::error_code ec;
  fs::create_directories(os::fsPath(s.out_dir), ec);
  printHeader(s, plan);
  summary.failed = static_cast<int>(plan.errors.size());
  const std::vector<PlannedOutput>& motions = plan.outputs;
  std::vector<ManifestEntry> manifest(motions.size());
  const bool record = !s.request.manifest.empty();
  const unsigned threads = s.request.writer.threads
                               ? static_cast<unsigned>(*s.request.writer.threads)
                               : hardwareThreads();
  const size_t workers = std::min<size_t>(threads, std::max<size_t>(1, motions.size()));
  // Files in parallel, or one file's FBX arrays in parallel, never both:
  // `workers` jobs each compressing on `threads` cores would run threads^2.
  const bool one_thread = workers > 1;
  std::atomic<size_t> next{0};
  std::mutex print;
  const SteadyTime batch_start = steadyNow();
  const bool eta =
      os::isTerminal(1);  // the time left, on a terminal only (output stays reproducible)
  size_t finished = 0;
  StageSeconds summed;  // the converted exports' stage times, over all workers
  BatchNotes notes(motions.size()), warnings(motions.size());
  // One line per finished file, "[k/N] what", under the print lock.
  auto progress = [&](const std::string& what) {
    ++finished;
    if (s.quiet) return;
    const double elapsed = secondsSince(batch_start);
    std::printf("%s%s\n", batchProgressPrefix(finished, motions.size(), elapsed, eta).c_str(),
                what.c_str());
    if (eta) std::fflush(stdout);
  };
  auto worker = [&] {
    for (size_t i; (i = next++) < motions.size();) {
      const SteadyTime start = steadyNow();
      auto seconds = [&] { return secondsSince(start); };
      const std::string& out = motions[i].out;
      ManifestEntry& entry = manifest[i];
      entry.input = motions[i].motion;
      if (motions[i].up_to_date) {
        describeOutput(out, record, &entry);
        entry.status = "up-to-date";
        entry.seconds = seconds();
        std::lock_guard<std::mutex> lock(print);
        ++summary.skipped;
        progress(out + ": up to date");
        continue;
      }
      if (noPoseData(motions[i].motion)) {
        entry.status = "skipped";
        entry.message = "no pose data (a shape file: betas/gender only)";
        entry.seconds = seconds();
        std::lock_guard<std::mutex> lock(print);
        ++summary.no_poses;
        progress(entry.input + ": skipped, " + entry.message);
        continue;
      }
      // Per motion: a folder picks the model by the decoded motion's kind and gender.
      Result<ExportReport> r =
          runExportJob(jobRequest(s.request, motions[i], one_thread), inputs, &models);
      if (r) describeOutput(out, record, &entry);
      entry.status = r ? "converted" : "failed";
      entry.message = r ? "" : r.message();
      entry.seconds = seconds();
      std::lock_guard<std::mutex> lock(print);
      if (!r) {
        ++summary.failed;
        std::fprintf(stderr, "%s\n", r.message().c_str());
        progress(entry.input + ": failed");
        continue;
      }
      ++summary.converted;
      summed.read += r->stages.read;
      summed.fit += r->stages.fit;
      summed.bake += r->stages.bake;
      summed.write += r->stages.write;
      const std::string name = os::utf8(os::fsPath(motions[i].motion).stem());
      notes.set(i, name, r->notes);
      if (!r->model_note.empty()) warnings.set(i, name, {r->model_note});
      char line[160];
      std::snprintf(line, sizeof line, ": %d frames, %.2f MB, %.0f ms, model ", r->frames,
                    r->bytes / 1e6, r->seconds * 1e3);
      progress(out + line + r->model_path);
    }
  };
  runWorkers(int(workers), [&](int, int) { worker(); });
  printFolded(notes, warnings, s.quiet);
  if (inputs.skins && inputs.skins->reused() > 0 && !s.quiet) {
    const int computed = inputs.skins->computed(), reused = inputs.skins->reused();
    std::printf(
        "batch: skin fit computed for %d subject%s, reused for %d motion%s (same model, "
        "betas and skin options)\n",
        computed, computed == 1 ? "" : "s", reused, reused == 1 ? "" : "s");
  }
  const double wall = secondsSince(batch_start);
  if (const std::string line = batchThroughputLine(summary.converted, wall, summed);
      !line.empty() && !s.quiet)
    std::printf("%s\n", line.c_str());
  std::printf("batch: %d converted, %d up to date, %d failed, %d skipped (no pose data)\n",
              summary.converted, summary.skipped, summary.failed, summary.no_poses);
  if (record)
    if (Status st = writeManifest(s.request.manifest, manifest); !st) {
      std::fprintf(stderr, "%s\n", errorLine("saving", s.request.manifest, st.message()).c_str());
      summary.manifest_failed = true;
    }
  return summary;
}

}  // namespace smpl
