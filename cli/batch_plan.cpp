// planBatch: listing (error_code overloads only: nothing here throws),
// collisions, input protection, stale temporaries, up-to-date decisions.
#include "cli/batch_plan.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "cli/batch_shard.h"
#include "core/io/file_io.h"
#include "core/io/sha256.h"
#include "core/motions/motion_layout.h"
#include "core/os/path.h"
#include "core/utf8.h"
#include "exporter/metadata_json.h"
#include "request/error_line.h"
#include "request/producer.h"
#include "request/run_paths.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

// A name with a motion extension of the reader table (core/motions/motion_layout.h),
// not one of our sidecars.
bool isMotionName(const std::string& name) {
  if (hasSuffix(name, ".smpl.json")) return false;
  for (const std::string& ext : motionFileExtensions())
    if (hasSuffix(name, ext)) return true;
  return false;
}

// The motions in `dir`; unreadable entries become errors/notes of `plan`.
Result<std::vector<std::string>> listMotions(const std::string& dir, BatchPlan* plan) {
  std::error_code ec;
  const fs::file_status st = fs::status(os::fsPath(dir), ec);
  if (ec || !fs::is_directory(st))
    return makeError(errorLine("loading", dir,
                               fs::exists(st) ? "not a directory (--motion-dir)"
                                              : "no such directory (--motion-dir)"),
                     ErrorKind::Load);
  std::vector<std::string> motions;
  auto it = fs::directory_iterator(os::fsPath(dir), ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const std::string path = os::utf8(it->path());
    if (!isMotionName(os::utf8(it->path().filename()))) continue;
    std::error_code entry_ec;
    const fs::file_status entry = it->status(entry_ec);  // follows symbolic links, once
    if (entry_ec)
      plan->errors.push_back(errorLine("loading", path, "cannot read: " + entry_ec.message()));
    else if (!fs::is_regular_file(entry))
      plan->notes.push_back(path + ": not a regular file; skipped");
    else
      motions.push_back(path);
  }
  if (ec) plan->errors.push_back(errorLine("loading", dir, "cannot list: " + ec.message()));
  std::sort(motions.begin(), motions.end());
  return motions;
}

bool olderThan(const std::string& a, const std::string& b) {
  std::error_code ec1, ec2;
  const auto ta = fs::last_write_time(os::fsPath(a), ec1),
             tb = fs::last_write_time(os::fsPath(b), ec2);
  return ec1 || ec2 || ta < tb;
}

// The files on disk are the ones the sidecar records (exporter/metadata_json.h
// "outputs": name, size, then SHA-256): an output truncated, replaced or
// missing its .bin is rebuilt even when its sidecar matches.
bool outputsAsRecorded(const std::vector<std::string>& outputs, const std::string& sidecar) {
  const std::vector<RecordedOutput> recorded = recordedOutputsOf(sidecar);
  if (recorded.size() != outputs.size()) return false;
  for (const std::string& o : outputs) {
    const std::string name = escapeInvalidUtf8(baseName(o));
    auto r = std::find_if(recorded.begin(), recorded.end(),
                          [&](const RecordedOutput& e) { return e.file == name; });
    std::error_code ec;
    if (r == recorded.end() || !fs::is_regular_file(os::fsPath(o), ec) ||
        fs::file_size(os::fsPath(o), ec) != r->bytes || ec)
      return false;
    Result<std::string> digest = sha256File(o);
    if (!digest || *digest != r->sha256) return false;
  }
  return true;
}

bool upToDate(const Settings& s, const PlannedOutput& p) {
  const std::string sidecar = p.out + ".smpl.json";
  std::error_code ec;
  if (!fs::is_regular_file(os::fsPath(p.out), ec) || !fs::is_regular_file(os::fsPath(sidecar), ec))
    return false;
  if (olderThan(p.out, p.motion) || olderThan(sidecar, p.motion)) return false;
  if (fs::file_size(os::fsPath(sidecar), ec) > (64u << 20) || ec) return false;
  Result<std::vector<uint8_t>> bytes = readFileBytes(sidecar);
  if (!bytes) return false;
  const std::string text(bytes->begin(), bytes->end());
  std::vector<std::string> outputs = {p.out};  // the output and a .gltf's buffer
  if (const std::string bin = gltfBufferPath(s.request, p.out); !bin.empty())
    outputs.push_back(bin);
  return producerHashOf(text) == p.producer_hash && outputsAsRecorded(outputs, text);
}

Status checkCollisions(const std::vector<PlannedOutput>& outputs) {
  std::map<std::string, std::string> first;  // output -> motion
  for (const PlannedOutput& p : outputs) {
    auto [it, fresh] = first.emplace(p.out, p.motion);
    if (!fresh)
      return makeError(it->second + " and " + p.motion + " would both write " + p.out +
                       "; rename one of them (batch outputs are named after the motion's stem)");
  }
  return Status();
}

Error usage(const std::string& message) {
  return makeError("Error in arguments: " + message, ErrorKind::Usage);
}

// --shard I/N: this run's share of the (sorted) motions.
void keepShard(const Settings& s, BatchPlan* plan) {
  if (s.shard_count <= 1) return;
  std::vector<std::string> all;
  for (const PlannedOutput& p : plan->outputs) all.push_back(p.motion);
  const std::vector<std::string> share =
      shardMotions(all, s.request.motion_dir, s.shard_index, s.shard_count);
  const std::set<std::string> keep(share.begin(), share.end());
  std::vector<PlannedOutput> kept;
  for (const PlannedOutput& p : plan->outputs)
    if (keep.count(p.motion)) kept.push_back(p);
  plan->outputs = std::move(kept);
}

}  // namespace

Result<BatchPlan> planBatch(const Settings& s) {
  BatchPlan plan;
  const WriterFormat* format = outputFormat(s);  // not null: beginRun checked --format
  Result<std::vector<std::string>> motions = listMotions(s.request.motion_dir, &plan);
  if (!motions) return motions.error();
  for (const std::string& m : *motions) {
    PlannedOutput p;
    p.motion = m;
    p.out = os::utf8(os::fsPath(s.out_dir) /
                     os::fsPath(os::utf8(os::fsPath(m).stem()) + format->extensions.front()));
    plan.outputs.push_back(p);
  }
  if (Status st = checkCollisions(plan.outputs); !st) return usage(st.message());
  plan.listed = plan.outputs.size();
  keepShard(s, &plan);
  std::vector<std::string> outs, names;
  for (const PlannedOutput& p : plan.outputs) {
    outs.push_back(p.out);
    for (const std::string& name : {p.out, p.out + ".smpl.json", gltfBufferPath(s.request, p.out)})
      if (!name.empty()) names.push_back(baseName(name));
  }
  // Every path of the run (every listed motion, this share's outputs, the manifest).
  if (Status st = checkRunPaths(runPaths(s.request, outs, *motions)); !st)
    return usage(st.message());
  Result<ContentHash> base = producerBase(s.request);
  if (!base)
    return makeError("Error loading " + base.message(), ErrorKind::Load);  // names the input file
  removeStaleTemps(s.out_dir, names);
  for (PlannedOutput& p : plan.outputs) {
    p.producer_hash = producerHash(*base, {p.motion});
    p.up_to_date = !s.force && upToDate(s, p);
  }
  return plan;
}

}  // namespace smpl
