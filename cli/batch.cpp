#include "cli/batch.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "cli/batch_shard.h"
#include "cli/export_job.h"
#include "cli/manifest.h"
#include "cli/sha256.h"
#include "core/load/motion.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> listMotions(const std::string& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".npz" || ext == ".json" || ext == ".smpl" || ext == ".pkl"))
      files.push_back(entry.path());
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

// Output size and digest for the manifest (only when one is written).
void describeOutput(const fs::path& out, bool manifest, ManifestEntry* e) {
  e->output = out.string();
  std::error_code ec;
  e->bytes = static_cast<size_t>(fs::file_size(out, ec));
  if (Result<std::string> digest = manifest ? sha256File(out.string()) : Result<std::string>(std::string()); digest)
    e->sha256 = *digest;
}

// No pose keys at all (AMASS shape.npz, *_stagei.npz): skipped, not failed.
// An unreadable file is left to the export, which reports it.
bool noPoseData(const fs::path& motion) {
  Result<bool> poses = hasPoseData(motion.string());
  return poses && !*poses;
}

}  // namespace

BatchSummary runBatch(const BodyModel& model, const Settings& s) {
  BatchSummary summary;
  std::error_code ec;
  fs::create_directories(s.out_dir, ec);
  const std::vector<fs::path> all = listMotions(s.motion_dir);
  const std::vector<fs::path> motions = shardMotions(all, s.motion_dir, s.shard_index, s.shard_count);
  if (all.empty()) std::fprintf(stderr, "Warning: no .npz, .json, .smpl or .pkl motions in %s\n", s.motion_dir.c_str());
  else if (motions.empty() && !s.quiet)
    std::printf("note: shard %d/%d of the %zu motions in %s is empty\n", s.shard_index, s.shard_count, all.size(),
                s.motion_dir.c_str());
  std::vector<ManifestEntry> manifest(motions.size());
  std::atomic<size_t> next{0};
  std::mutex print;
  auto worker = [&] {
    for (size_t i; (i = next++) < motions.size();) {
      const auto start = std::chrono::steady_clock::now();
      const fs::path out = fs::path(s.out_dir) / (motions[i].stem().string() + "." + s.format);
      ManifestEntry& entry = manifest[i];
      entry.input = motions[i].string();
      auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
      if (upToDate(out, motions[i], s.model)) {
        describeOutput(out, !s.manifest.empty(), &entry);
        entry.status = "up-to-date";
        entry.seconds = seconds();
        std::lock_guard<std::mutex> lock(print);
        ++summary.skipped;
        continue;
      }
      if (noPoseData(motions[i])) {
        entry.status = "skipped";
        entry.message = "no pose data (a shape file: betas/gender only)";
        entry.seconds = seconds();
        std::lock_guard<std::mutex> lock(print);
        ++summary.no_poses;
        if (!s.quiet) std::printf("note: skipped %s: %s\n", entry.input.c_str(), entry.message.c_str());
        continue;
      }
      JobFailure failure{kExitOk, ""};
      Result<ExportReport> r = runExport(model, s, ExportJob{out.string(), {motions[i].string()}, false}, &failure);
      if (r) describeOutput(out, !s.manifest.empty(), &entry);
      entry.status = r ? "converted" : "failed";
      entry.message = r ? "" : failure.message;
      entry.seconds = seconds();
      std::lock_guard<std::mutex> lock(print);
      if (!r) {
        ++summary.failed;
        std::fprintf(stderr, "%s\n", failure.message.c_str());
        continue;
      }
      ++summary.converted;
      if (s.quiet) continue;
      std::printf("%s: %d frames, %.2f MB, %.0f ms\n", out.c_str(), r->frames, r->bytes / 1e6, r->seconds * 1e3);
      for (const std::string& note : r->notes) std::printf("note: %s\n", note.c_str());
    }
  };
  const unsigned threads = s.threads > 0 ? s.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<size_t>(threads, std::max<size_t>(1, motions.size())); ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  std::printf("batch: %d converted, %d up to date, %d skipped (no pose data), %d failed\n", summary.converted,
              summary.skipped, summary.no_poses, summary.failed);
  if (!s.manifest.empty())
    if (Status st = writeManifest(s.manifest, manifest); !st) {
      std::fprintf(stderr, "%s\n", errorLine("saving", s.manifest, st.message()).c_str());
      summary.manifest_failed = true;
    }
  return summary;
}

}  // namespace smpl
