#include "cli/export_job.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <new>

#include "cli/dmpl_job.h"
#include "cli/output_guard.h"
#include "cli/producer.h"
#include "core/io/file_io.h"
#include "core/io/printable.h"
#include "core/load/motion.h"
#include "core/load/motion_fit.h"
#include "exporter/animation.h"
#include "exporter/export_asset.h"
#include "exporter/metadata_json.h"
#include "exporter/pipeline.h"
#include "exporter/pruning_error.h"
#include "plugins/writer.h"

namespace smpl {
namespace {

Error fail(ErrorKind kind, const std::string& verb, const std::string& path,
           const std::string& message) {
  return makeError(errorLine(verb, path, message), kind);
}

// An export error that is really about the options (too many betas for the
// model, --shape-keys beyond its directions) is a usage error.
// An input read while building (the --uv file) fails as a load error.
Error exportFailure(const std::string& out, const Error& e, const std::string& input = "") {
  if (e.kind == ErrorKind::Usage) return fail(ErrorKind::Usage, "in", "arguments", e.message);
  if (e.kind == ErrorKind::Load) return fail(ErrorKind::Load, "loading", input, e.message);
  return fail(ErrorKind::Export, "exporting", out, e.message);
}

void drawProgress(const std::string& name, double fraction) {
  const int width = 30, filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r%-24.24s [%s%s] %3d%%", name.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100));
  if (fraction >= 1.0) std::fprintf(stderr, "\n");
}

Result<std::vector<Motion>> loadMotions(const BodyModel& model, const Settings& s,
                                        const ExportJob& job) {
  std::vector<Motion> motions;
  MotionOptions options;
  options.source_fps = s.source_fps;
  for (const std::string& path : job.motions) {
    Result<Motion> m = loadMotion(path, options);
    if (!m) return fail(ErrorKind::Load, "loading", path, m.message());
    // Fit hands need the model's PCA basis and mean.
    if (Status st = resolveFitHands(model, s.flat_hand_mean, path, &*m); !st)
      return fail(ErrorKind::Load, "loading", path, st.message());
    motions.push_back(std::move(*m));
  }
  return motions;
}

// Betas from the first motion when the user gave none; --betas-from-motion
// makes a motion without betas an error.
Status betasFromMotion(const BodyModel& model, const Settings& s, const ExportJob& job,
                       const std::vector<Motion>& motions, ExportOptions* o) {
  if (motions.empty() || motions[0].betas.empty()) {
    if (s.betas_from_motion && !job.motions.empty())
      return fail(ErrorKind::Load, "loading", job.motions[0],
                  "no betas in the motion (--betas-from-motion)");
    return Status();
  }
  const size_t n = std::min(motions[0].betas.size(), static_cast<size_t>(model.numBetas()));
  o->betas.assign(motions[0].betas.begin(), motions[0].betas.begin() + n);
  return Status();
}

// --frames A:B applies to each motion, clamped to its length; `note` (if not
// null) gets the line saying so, or stays empty.
AnimationOptions framesFor(const AnimationOptions& animation, const Motion& m, std::string* note) {
  AnimationOptions frames = animation;
  const int total = static_cast<int>(m.frames.size());
  if (frames.end_frame > total && frames.first_frame < total) {
    if (note)
      *note = m.name + ": --frames " + std::to_string(frames.first_frame) + ":" +
              std::to_string(frames.end_frame) + " ends after the motion's " +
              std::to_string(total) + " frames; baked frames " +
              std::to_string(frames.first_frame) + ":" + std::to_string(total);
    frames.end_frame = total;
  }
  return frames;
}

// What exportAsset bakes: each motion with the job's frame range (clamped per
// motion) and, on a terminal, a progress bar.
std::vector<MotionInput> motionInputs(const Settings& s, const ExportJob& job,
                                      const std::vector<Motion>& motions) {
  std::vector<MotionInput> inputs;
  for (size_t i = 0; i < motions.size(); ++i) {
    MotionInput in{&motions[i], job.motions[i], framesFor(s.animation, motions[i], nullptr),
                   nullptr};
    if (job.progress) in.progress = [name = motions[i].name](double f) { drawProgress(name, f); };
    inputs.push_back(std::move(in));
  }
  return inputs;
}

// The motions' notes and frame counts for the summary.
void reportMotions(const BodyModel& model, const Settings& s, const ExportJob& job,
                   const std::vector<Motion>& motions, const Asset& asset, ExportReport* report) {
  for (size_t i = 0; i < motions.size(); ++i) {
    const Motion& m = motions[i];
    for (const std::string& note : m.notes)  // a betas note matters only where those betas are used
      if (note.rfind("betas:", 0) != 0 || (!s.betas_given && i == 0))
        report->notes.push_back(m.name + ": " + note);
    std::string frames_note;  // --frames clamped to this motion's length
    framesFor(s.animation, m, &frames_note);
    if (!frames_note.empty()) report->notes.push_back(frames_note);
    Result<MotionMapping> mapping = mapMotion(model, m, job.motions[i]);
    if (mapping && !mapping->dropped.empty())
      report->notes.push_back(m.name + ": " + std::to_string(mapping->dropped.size()) + " " +
                              modelKindName(m.layout) + " joints not in the model were dropped (" +
                              mapping->dropped.front() + ", ...)");
    if (i < asset.animations.size())
      report->frames += static_cast<int>(asset.animations[i].times.size());
  }
}

// The output and its sidecar go together; the sidecar (what produced the
// output, and the size and SHA-256 of each file written with it) is renamed
// last, so it is the commit record (file_io.h).
Status writeOutputs(const std::string& out, const Writer::Files& files,
                    const std::string& buffer_path, const Asset& asset,
                    const std::string& producer) {
  std::vector<FileContent> contents = {FileContent{out, files.bytes.data(), files.bytes.size()}};
  if (!buffer_path.empty())
    contents.push_back(FileContent{buffer_path, files.buffer.data(), files.buffer.size()});
  const std::string sidecar = sidecarJson(asset, producer, contents);
  contents.push_back(FileContent{out + ".smpl.json", sidecar.data(), sidecar.size()});
  return writeFilesTogether(contents);
}

Result<std::string> producerHashFor(const Settings& s, const ExportJob& job) {
  if (!job.producer_hash.empty()) return job.producer_hash;
  Result<ContentHash> base = producerBase(s);
  if (!base) return base.error();
  return producerHash(*base, job.motions);
}

}  // namespace

std::string errorLine(const std::string& verb, const std::string& path,
                      const std::string& message) {
  // Paths and messages may carry bytes from files or the command line: one
  // printable line. A long path loses its middle (each time it appears), and
  // a line still over 4 KiB loses its middle too: the reason, last, stays.
  constexpr size_t kPathBytes = 1024, kLineBytes = 4096;
  const std::string full = printable(path, static_cast<size_t>(-1));
  const std::string shown = printableMiddle(path, kPathBytes);
  std::string text = printable(message, static_cast<size_t>(-1));
  for (size_t at = 0;
       full != shown && !full.empty() && (at = text.find(full, at)) != std::string::npos;
       at += shown.size())
    text.replace(at, full.size(), shown);
  if (text.compare(0, shown.size() + 1, shown + ":") == 0)
    return printableMiddle("Error " + verb + " " + text, kLineBytes);
  return printableMiddle("Error " + verb + " " + shown + ": " + text, kLineBytes);
}

namespace {

Result<ExportReport> runExportUnguarded(const BodyModel& model, const Settings& s,
                                        const ExportJob& job) {
  const auto start = std::chrono::steady_clock::now();
  const Writer* writer = writerForPath(job.out);
  if (!writer) return fail(ErrorKind::Usage, "in", "arguments", "no writer for " + job.out);
  if (job.producer_hash.empty())  // a batch (planBatch) cleans all its outputs' temporaries at once
    removeStaleTemps(dirName(job.out), {baseName(job.out), baseName(job.out) + ".smpl.json",
                                        baseName(gltfBufferPath(s, job.out))});
  Result<std::vector<Motion>> motions = loadMotions(model, s, job);
  if (!motions) return motions.error();
  ExportOptions options = s.export_options;
  if (!s.betas_given)
    if (Status st = betasFromMotion(model, s, job, *motions, &options); !st) return st.error();
  // Baked weights must survive importers that clamp (exportAsset resolves Auto the same way).
  options.encoding =
      resolveEncoding(options.encoding, motions->size(), options.corrective_basis > 0);
  options.quantize_morphs = s.writer_options.quantize_morphs;
  // The finished asset: baked, quantisation folded, validated; the writer only translates it.
  ExportReport report;
  Result<PreparedDmpl> dmpl = prepareDmpl(model, s, job, *motions, &report);  // --dmpl (dmpl_job.h)
  if (!dmpl) return dmpl.error();
  Result<Asset> asset = exportAsset(model, options, motionInputs(s, job, *motions), &dmpl->input);
  if (!asset) return exportFailure(job.out, asset.error(), options.uv_obj);
  reportMotions(model, s, job, *motions, *asset, &report);
  noteDmplJointCost(*asset, &report);
  if (s.writer_options.quantize_morphs && (options.shape_keys > 0 || options.expression_keys > 0))
    report.notes.push_back(
        "--quantize-morphs: shape_/expr_ targets stay float (their weights are the coefficients)");
  Result<std::string> producer = producerHashFor(s, job);
  if (!producer) return fail(ErrorKind::Load, "loading", s.model, producer.message());
  WriterOptions writer_options = s.writer_options;
  const std::string buffer_path = gltfBufferPath(s, job.out);
  writer_options.buffer_uri = baseName(buffer_path);
  Result<Writer::Files> files = writer->serializeFiles(*asset, writer_options);
  if (!files) return exportFailure(job.out, files.error());
  if (Status st = writeOutputs(job.out, *files, buffer_path, *asset, *producer); !st)
    return fail(ErrorKind::Write, "saving", job.out, st.message());
  report.options = options;
  report.skin = skinOfAsset(asset->mesh, model.numVertices());
  report.bytes = files->bytes.size() + files->buffer.size();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.vertices = static_cast<int>(asset->mesh.positions.rows());
  report.joints = static_cast<int>(asset->skeleton.names.size());
  report.morph_targets = static_cast<int>(asset->mesh.morph_targets.size());
  report.max_influences = asset->metadata.max_influences;
  return report;
}

}  // namespace

// Batch jobs run on worker threads, where an escaping exception would abort
// the process: the job's own last-resort catch turns it into a job failure.
Result<ExportReport> runExport(const BodyModel& model, const Settings& s, const ExportJob& job) {
  try {
    return runExportUnguarded(model, s, job);
  } catch (const std::bad_alloc&) {
    return fail(ErrorKind::Export, "exporting", job.out,
                "out of memory (set a lower --memory-limit)");
  } catch (const std::exception& e) {
    return fail(ErrorKind::Export, "exporting", job.out,
                std::string("internal error: ") + e.what());
  }
}

}  // namespace smpl
