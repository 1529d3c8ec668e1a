// beginRun / loadRunInputs / runExportJob / runExportRequest: see run_request.h.
#include "request/run_request.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <unordered_map>

#include "core/heap_trim.h"
#include "core/io/file_io.h"
#include "core/io/name_component.h"
#include "core/io/printable.h"
#include "core/memory_budget.h"
#include "core/models/betas_file.h"
#include "core/parallel.h"
#include "core/stopwatch.h"
#include "exporter/export_asset.h"
#include "exporter/metadata_json.h"
#include "exporter/scene_timeline.h"
#include "request/check_request.h"
#include "request/dmpl_job.h"
#include "request/error_line.h"
#include "request/hand_side.h"
#include "request/motion_notes.h"
#include "request/producer.h"
#include "request/request_hands.h"
#include "request/request_motions.h"
#include "request/request_options.h"
#include "request/run_paths.h"
#include "writers/writer.h"

namespace smpl {
namespace {

// What the run is doing, for the line of an exception that escapes.
struct Stage {
  const char* verb = "in";
  std::string path = "arguments";
  ErrorKind kind = ErrorKind::Usage;
  void set(const char* v, const std::string& p, ErrorKind k) { verb = v, path = p, kind = k; }
};

Error fail(ErrorKind kind, const char* verb, const std::string& path, const std::string& message) {
  return makeError(errorLine(verb, path, message), kind);
}

Error usage(const std::string& message) {
  return fail(ErrorKind::Usage, "in", "arguments", message);
}

// Runs `body` and turns an escaping exception into the stage's error line.
template <class T, class Body>
Result<T> guarded(Stage* stage, Body body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return fail(stage->kind, stage->verb, stage->path,
                "out of memory (the system refused an allocation below --memory-limit " +
                    formatBytes(memoryLimit()) + "; set a lower limit)");
  } catch (const std::exception& e) {
    return fail(stage->kind, stage->verb, stage->path, std::string("internal error: ") + e.what());
  }
}

// An export error that is really about the options is a usage error; an
// input read while building (the --uv file) fails as a load error.
Error exportFailure(const std::string& out, const Error& e, const std::string& input) {
  if (e.kind == ErrorKind::Usage) return usage(e.message);
  if (e.kind == ErrorKind::Load) return fail(ErrorKind::Load, "loading", input, e.message);
  return fail(ErrorKind::Export, "exporting", out, e.message);
}

// The motions decoded once, the model picked with the first (mirrored for a
// hand of the other side: hand_side.h), the model's checks, then the fit
// hands through the model's basis and the --hands tracks into the first.
struct Loaded {
  std::vector<Motion> motions;
  ModelPick pick;
  HandSideModel side;  // owns pick.model when it is the mirrored model
};

Result<Loaded> loadJob(const ExportRequest& r, const RunInputs& inputs, ModelSource* models,
                       Stage* stage, std::vector<Motion> given) {
  Loaded loaded;
  // The first motions decoded by the caller: a track of --track all, or the
  // Python module's motions (read from memory).
  loaded.motions = std::move(given);
  for (size_t i = loaded.motions.size(); i < r.motions.size();
       ++i) {  // exceptions: "exporting <out>"
    const std::string& path = r.motions[i];
    Result<Motion> m = decodeMotion(path, r);
    if (!m) return fail(ErrorKind::Load, "loading", path, m.message());
    loaded.motions.push_back(std::move(*m));
  }
  stage->set("loading", r.model, ErrorKind::Load);  // a folder's pick loads its model here
  Result<ModelPick> pick = models->forMotion(loaded.motions.empty() ? nullptr : &loaded.motions[0]);
  if (!pick) return fail(ErrorKind::Load, "loading", r.model, pick.message());
  stage->set("exporting", r.out, ErrorKind::Export);
  loaded.pick = *pick;
  Result<HandSideModel> side = modelForHandSide(*pick->model, r.motions, &loaded.motions);
  if (!side) return fail(ErrorKind::Load, "loading", r.motions.front(), side.message());
  loaded.side = std::move(*side);
  if (loaded.side.mirrored) loaded.pick.model = loaded.side.mirrored.get();
  const BodyModel& model = *loaded.pick.model;
  if (Status st = checkRequestForModel(r, inputs.betas, model); !st) return usage(st.message());
  for (size_t i = 0; i < r.motions.size(); ++i)
    if (Status st = resolveMotionHands(model, r, r.motions[i], &loaded.motions[i]); !st)
      return fail(ErrorKind::Load, "loading", r.motions[i], st.message());
  if (!r.hands.empty()) {
    std::string about;
    if (Status st = applyRequestHands(model, r, r.motions.front(), &loaded.motions.front(), &about);
        !st)
      return fail(ErrorKind::Load, "loading", about, st.message());
  }
  return loaded;
}

// Betas from the first motion when the run gave none; --betas-from-motion
// makes a motion without betas an error.
Status betasFromMotion(const BodyModel& model, const ExportRequest& r,
                       const std::vector<Motion>& motions, ExportOptions* o,
                       std::vector<std::string>* notes) {
  if (motions.empty() || motions[0].betas.empty()) {
    if (r.betas_from_motion && !r.motions.empty())
      return fail(ErrorKind::Load, "loading", r.motions[0],
                  "no betas in the motion (--betas-from-motion)");
    return Status();
  }
  const std::vector<double>& betas = motions[0].betas;
  const size_t n = std::min(betas.size(), static_cast<size_t>(model.numBetas()));
  o->betas.assign(betas.begin(), betas.begin() + n);
  double dropped = 0;
  for (size_t i = n; i < betas.size(); ++i) dropped = std::max(dropped, std::abs(betas[i]));
  if (dropped > 0) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "%s: the motion has %zu betas; the model %s has %d: betas %zu..%zu are not "
                  "used (largest |value| %.3g)",
                  motions[0].name.c_str(), betas.size(), model.name.c_str(), model.numBetas(), n,
                  betas.size() - 1, dropped);
    notes->push_back(text);
  }
  return Status();
}

// What exportAsset bakes: each motion with the request's frame range
// (clamped per motion, the note kept in `frame_notes`) and progress.
// The job owns the motions and frees their frames once baked (runJob), so
// the bake may free them as it goes (MotionInput::release).
std::vector<MotionInput> motionInputs(const ExportRequest& r, std::vector<Motion>* motions,
                                      std::vector<std::string>* frame_notes) {
  std::vector<MotionInput> inputs;
  const AnimationOptions& animation = r.animation;
  for (size_t i = 0; i < motions->size(); ++i) {
    Motion& motion = (*motions)[i];
    frame_notes->emplace_back();
    MotionInput in{&motion, r.motions[i], framesFor(animation, motion, &frame_notes->back()),
                   nullptr, &motion};
    if (r.progress) in.progress = [&r, name = motion.name](double f) { r.progress(name, f); };
    inputs.push_back(std::move(in));
  }
  return inputs;
}

// The finished asset and the notes that go with it.
Result<Asset> buildJob(const ExportRequest& r, const RunInputs& inputs, Loaded* job,
                       ExportReport* report) {
  Loaded& loaded = *job;
  const BodyModel& model = *loaded.pick.model;
  ExportOptions options = exportOptionsOf(r, inputs.betas);
  if (!inputs.betas_given)
    if (Status st = betasFromMotion(model, r, loaded.motions, &options, &report->notes); !st)
      return st.error();
  Result<PreparedDmpl> dmpl = prepareDmpl(model, r, loaded.motions, report);  // dmpl_job.h
  if (!dmpl) return dmpl.error();
  std::vector<std::string> frame_notes;
  // A mirrored hand model belongs to this job: its skin is not kept for others.
  SkinCache* skins = loaded.side.mirrored ? nullptr : inputs.skins.get();
  ExportTimes times;
  Result<Asset> asset = exportAsset(model, options, motionInputs(r, &loaded.motions, &frame_notes),
                                    &dmpl->input, skins, &times);
  report->stages.fit = times.fit;
  report->stages.bake = times.bake;
  if (!asset) return exportFailure(r.out, asset.error(), options.uv_obj);
  noteMotions(loaded.motions, frame_notes, inputs.betas_given, *asset, report);
  noteDmplJointCost(*asset, report);
  if (r.asset.quantize_morphs && (options.shape_keys > 0 || options.expression_keys > 0))
    report->notes.push_back(
        "--quantize-morphs: shape_/expr_ targets stay float (their weights are the coefficients)");
  report->options = options;
  return asset;
}

// The output file's bytes in memory, as writeFilesTogether would write them:
// the serialised head, then the tail parts (a GLB's BIN chunk, splices).
Result<size_t> keepJob(const ExportRequest& r, const Asset& asset, const Writer& writer,
                       std::string* memory) {
  Result<Writer::Files> files = writer.serializeFiles(asset, writerOptionsOf(r, ""));
  if (!files) return exportFailure(r.out, files.error(), "");
  *memory = std::move(files->bytes);
  memory->reserve(files->size());
  for (const ByteSpan& part : files->tailParts())
    memory->append(static_cast<const char*>(part.data), part.size);
  return memory->size();
}

// Freed frames worth handing back to the system before the write.
constexpr uint64_t kTrimAfter = uint64_t(32) << 20;

// Whether a serial stage may run beside another on a thread of its own:
// not with --threads 1 (the export's count: a batch job's writer has one
// thread, its export the run's --threads).
bool besideAllowed(const ExportRequest& r) { return exportThreads(r) != 1; }

// The producer hash of the request's output (request/producer.h).
Result<std::string> producerOf(const ExportRequest& r) {
  if (!r.producer_hash.empty()) return r.producer_hash;
  Result<ContentHash> base = producerBase(r);
  if (!base) return fail(ErrorKind::Load, "loading", r.model, base.message());
  return producerHash(*base, r.motions, r.hands);
}

// Commit the serialised output, its buffer and its sidecar (renamed last:
// the commit record, file_io.h); `sidecar` makes the sidecar's text from
// the producer hash and the files it records.
template <class Sidecar>
Result<size_t> commitFiles(const ExportRequest& r, const std::string& buffer_path,
                           Result<Writer::Files> files, Sidecar sidecar) {
  Result<std::string> producer = producerOf(r);
  if (!producer) return producer.error();
  if (!files) return exportFailure(r.out, files.error(), "");
  std::vector<FileContent> contents = {
      FileContent{r.out, files->bytes.data(), files->bytes.size(), files->tailParts()}};
  if (!buffer_path.empty())
    contents.push_back(FileContent{buffer_path, files->buffer.data(), files->buffer.size()});
  // The sidecar records the size and SHA-256 of each file written with it
  // (batch mode checks them, metadata_json.h): hashed while they are written.
  if (Status st = writeFilesWithRecord(
          contents, r.out + ".smpl.json", [&] { return sidecar(*producer, contents); },
          besideAllowed(r));
      !st)
    return fail(ErrorKind::Write, "saving", r.out, st.message());
  return files->size() + files->buffer.size();
}

// Serialise and commit the output, its buffer and its sidecar; with
// `memory`, keep the output there instead (nothing is written, no sidecar).
Result<size_t> writeJob(const ExportRequest& r, const Asset& asset, const Writer& writer,
                        std::string* memory) {
  if (memory) return keepJob(r, asset, writer, memory);
  const std::string buffer_path = gltfBufferPath(r, r.out);
  return commitFiles(r, buffer_path, writer.serializeFiles(asset, writerOptionsOf(r, buffer_path)),
                     [&](const std::string& producer, const std::vector<FileContent>& contents) {
                       return sidecarJson(asset, producer, contents);
                     });
}

Result<ExportReport> runJob(const ExportRequest& r, const RunInputs& inputs, ModelSource* models,
                            Stage* stage, std::vector<Motion> given = {},
                            std::string* memory = nullptr) {
  const SteadyTime start = steadyNow();
  const Writer* writer = writerForPath(r.out);
  if (!writer) return usage("no writer for " + r.out);  // checkRequest refused it first
  if (r.clean_temporaries && !memory)
    removeStaleTemps(dirName(r.out), {baseName(r.out), baseName(r.out) + ".smpl.json",
                                      baseName(gltfBufferPath(r, r.out))});
  Result<Loaded> loaded = loadJob(r, inputs, models, stage, std::move(given));
  if (!loaded) return loaded.error();
  ExportReport report;
  report.stages.read = secondsSince(start);
  report.out = r.out;
  report.model_path = loaded->pick.path;
  report.model_note = loaded->pick.note;
  report.betas_note = inputs.betas_note;
  Result<Asset> asset = buildJob(r, inputs, &*loaded, &report);
  if (!asset) return asset.error();
  // The baked clips hold all the writer needs: the decoded frames are freed
  // first, so a long clip peaks in the bake or in the write, not in both.
  const uint64_t charged = memoryCharged();
  for (Motion& m : loaded->motions) releaseFrames(&m);
  const bool frames_freed = charged >= memoryCharged() + kTrimAfter;
  const BodyModel& model = *loaded->pick.model;
  report.skin_fitted = asset->mesh.joints.cols() > 0;  // no skin for a skeleton-only writer
  if (report.skin_fitted) report.skin = skinOfAsset(asset->mesh, model.numVertices());
  if (report.skin_fitted && asset->placement.root_bone)  // model joint k is file joint k + 1
    report.skin.joints = (report.skin.joints.array() - 1).cwiseMax(0).matrix();
  // The refit is in the morph targets already; only the measurement reads it.
  const bool measure = r.skin_error_poses > 0 && report.skin_fitted;
  if (!measure) asset->corrective_refit = std::make_shared<CorrectiveRefit>();
  // A long clip's frames (small blocks) go back to the system before the
  // write; a short clip's stay for the next allocations (a batch's next job
  // would fault them in again, at a cost larger than the memory saved).
  if (frames_freed) returnFreedHeap();
  std::optional<Result<size_t>> bytes;
  std::optional<Result<PruningError>> err;
  const auto write = [&] {
    const SteadyTime write_start = steadyNow();
    bytes = writeJob(r, *asset, *writer, memory);
    report.stages.write = secondsSince(write_start);
  };
  const auto measure_error = [&] {
    if (measure)
      err = measurePruningError(model, report.options, r.skin_error_poses, &report.skin,
                                asset->corrective_refit.get());
  };
  // The write is serial: without clips the measurement (its own memory, not
  // a clip's) runs beside it. With clips it runs after the write, once a
  // long clip's tracks are gone; with --threads 1, after it too.
  if (measure && asset->animations.empty() && besideAllowed(r)) {
    runTogether(true, write, measure_error);
  } else {
    write();
    if (*bytes && measure) {
      asset->animations.clear();
      returnFreedHeap();
      measure_error();
    }
  }
  if (!*bytes) return bytes->error();
  if (err) {
    if (!*err) return fail(ErrorKind::Export, "measuring", r.out, err->message());
    report.skin_error = **err;
    report.skin_error_measured = true;
  }
  report.bytes = **bytes;
  report.placement = asset->placement;
  report.seconds = secondsSince(start);
  report.vertices = static_cast<int>(asset->mesh.positions.rows());
  report.joints = static_cast<int>(asset->skeleton.names.size());
  report.morph_targets = static_cast<int>(asset->mesh.morph_targets.size());
  report.max_influences = asset->metadata.max_influences;
  return report;
}

}  // namespace

Status beginRun(const ExportRequest& r) {
  if (Status st = checkRequest(r); !st) return usage(st.message());
  setMemoryLimit(r.memory_limit);
  return Status();
}

Result<RunInputs> loadRunInputs(const ExportRequest& r, ModelSource* models) {
  Stage stage;
  return guarded<RunInputs>(&stage, [&]() -> Result<RunInputs> {
    RunInputs inputs;
    inputs.betas = r.asset.betas;
    inputs.betas_given = !r.asset.betas.empty() || !r.betas_file.empty();
    if (!r.betas_file.empty()) {
      stage.set("loading", r.betas_file, ErrorKind::Load);
      std::string note;  // per-frame (T,B) betas that differ: their mean, with a note
      Result<std::vector<double>> betas = readBetasFile(r.betas_file, &note);
      if (!betas) return fail(ErrorKind::Load, "loading", r.betas_file, betas.message());
      inputs.betas = *betas;
      if (!note.empty()) inputs.betas_note = printable(r.betas_file) + ": " + note;
    }
    stage.set("loading", r.model, ErrorKind::Load);
    if (!models->isFolder()) {  // one model for the whole run: loaded before any motion
      Result<ModelPick> one = models->forMotion(nullptr);
      if (!one) return fail(ErrorKind::Load, "loading", r.model, one.message());
    }
    return inputs;
  });
}

Result<ExportReport> runExportJob(const ExportRequest& r, const RunInputs& inputs,
                                  ModelSource* models) {
  Stage stage;
  stage.set("exporting", r.out, ErrorKind::Export);
  return guarded<ExportReport>(&stage, [&] { return runJob(r, inputs, models, &stage); });
}

// What can be known before the first track is written: no two tracks share
// an output (names from safeNameComponent are distinct, so only a hash
// collision of two long ids could), and every file name of every track fits
// NAME_MAX (a long --out stem), so a run never fails at track 5 after
// committing tracks 1-4.
Status checkTrackOutputs(const std::string& motion, const std::vector<Motion>& tracks,
                         const std::vector<std::string>& outs, const RunPaths& paths) {
  std::unordered_map<std::string, size_t> first;
  for (size_t i = 0; i < outs.size(); ++i) {
    const auto [at, fresh] = first.emplace(outs[i], i);
    if (!fresh)
      return fail(ErrorKind::Load, "loading", motion,
                  "tracks '" + printable(tracks[at->second].track, 64) + "' and '" +
                      printable(tracks[i].track, 64) + "' would both be written to " +
                      printable(outs[i]));
  }
  constexpr size_t kNameMax = 255;  // NAME_MAX; the atomic writer refuses longer names too
  for (const std::string& path : paths.outputs)
    if (baseName(path).size() > kNameMax)
      return fail(ErrorKind::Write, "saving", path, "cannot create: File name too long");
  return Status();
}

// --frames A:B against every track before the first is written: a start at
// or after a short track's last frame fails the export (exporter/animation.h
// checkFrames), and it would fail only after the tracks before it were
// committed. An end beyond a track's length is trimmed (framesFor), as for one motion.
Status checkTrackFrames(const ExportRequest& r, const std::vector<Motion>& tracks) {
  for (const Motion& m : tracks) {
    const int total = static_cast<int>(m.frames.size());
    const int end = r.animation.end_frame < 0 ? total : std::min(r.animation.end_frame, total);
    if (r.animation.first_frame < end) continue;
    return fail(ErrorKind::Export, "exporting", r.motions.front(),
                "track " + printable(m.track, 64) + ": --frames " +
                    std::to_string(r.animation.first_frame) + ":" +
                    std::to_string(r.animation.end_frame) + " is outside the track's " +
                    std::to_string(total) + " frames (nothing written)");
  }
  return Status();
}

// A track's failure that no check could foresee (a full disk): the tracks
// before it are complete and stay; the error says which they are.
Error writtenBefore(Error e, const std::vector<std::string>& outs, size_t failed) {
  if (failed == 0) return e;
  std::string names;
  for (size_t i = 0; i < failed; ++i) names += (i ? ", " : "") + baseName(outs[i]);
  e.message += " (written before it, complete: " + printable(names, 400) + ")";
  return e;
}

Result<std::vector<ExportReport>> runTrackExports(const ExportRequest& r, ModelSource* models) {
  if (Status st = beginRun(r); !st) return st.error();
  Stage stage;
  stage.set("loading", r.motions.front(), ErrorKind::Load);
  Result<std::vector<Motion>> tracks =
      guarded<std::vector<Motion>>(&stage, [&]() -> Result<std::vector<Motion>> {
        Result<MotionSet> set = decodeMotionSet(r.motions.front(), r);
        if (!set) return fail(ErrorKind::Load, "loading", r.motions.front(), set.message());
        Result<std::vector<Motion>> all = selectTracks(std::move(*set), r.track, r.motions.front());
        if (!all) return fail(ErrorKind::Load, "loading", r.motions.front(), all.message());
        return all;
      });
  if (!tracks) return tracks.error();
  std::vector<std::string> outs;  // known now, guarded before anything is written
  for (const Motion& m : *tracks)
    outs.push_back(tracks->size() == 1 ? r.out : trackOutput(r.out, m.track));
  const RunPaths paths = runPaths(r, outs, r.motions);
  if (Status st = checkTrackOutputs(r.motions.front(), *tracks, outs, paths); !st)
    return st.error();
  if (Status st = checkTrackFrames(r, *tracks); !st) return st.error();
  if (Status st = checkRunPaths(paths); !st) return usage(st.message());
  Result<RunInputs> inputs = loadRunInputs(r, models);
  if (!inputs) return inputs.error();
  std::vector<ExportReport> reports;
  for (size_t i = 0; i < tracks->size(); ++i) {
    ExportRequest job = r;
    job.out = outs[i];
    stage.set("exporting", job.out, ErrorKind::Export);
    Result<ExportReport> one = guarded<ExportReport>(&stage, [&] {
      std::vector<Motion> given;
      given.push_back(std::move((*tracks)[i]));
      return runJob(job, *inputs, models, &stage, std::move(given));
    });
    if (!one) return writtenBefore(one.error(), outs, i);
    reports.push_back(std::move(*one));
  }
  return reports;
}

namespace {

// The name of the body of track `id`: --name for a file without track ids,
// else --name + "_" + the id as one safe name component (core/io/name_component.h).
std::string bodyName(const std::string& name, const std::string& id) {
  return id.empty() ? name : name + "_" + safeNameComponent(id);
}

// Every track of the request's one motion, decoded once, and the file's camera.
Result<MotionSet> sceneTracks(const ExportRequest& r, Stage* stage) {
  const std::string& path = r.motions.front();
  stage->set("loading", path, ErrorKind::Load);
  Result<MotionSet> set = decodeMotionSet(path, r);
  if (!set) return fail(ErrorKind::Load, "loading", path, set.message());
  SceneCamera camera = std::move(set->camera);
  TrackChoice all;
  all.kind = TrackChoice::Kind::All;
  Result<std::vector<Motion>> tracks = selectTracks(std::move(*set), all, path);
  if (!tracks) return fail(ErrorKind::Load, "loading", path, tracks.message());
  for (const Motion& m : *tracks)
    if (m.fps != tracks->front().fps)
      return fail(ErrorKind::Load, "loading", path,
                  "tracks '" + printable(tracks->front().track, 64) + "' and '" +
                      printable(m.track, 64) + "' have different frame rates (" +
                      std::to_string(tracks->front().fps) + " and " + std::to_string(m.fps) +
                      " fps): a scene has one timeline");
  MotionSet out;
  out.tracks = std::move(*tracks);
  out.camera = std::move(camera);
  return out;
}

// One body of the scene: the one-body export's load and build (loadJob,
// buildJob) of `track` under the body's name, its notes into `report`.
Result<Asset> sceneBody(const ExportRequest& r, const RunInputs& inputs, ModelSource* models,
                        Stage* stage, Motion track, ExportReport* report) {
  ExportRequest job = r;
  job.asset.name = bodyName(r.asset.name, track.track);
  std::vector<Motion> given;
  given.push_back(std::move(track));
  Result<Loaded> loaded = loadJob(job, inputs, models, stage, std::move(given));
  if (!loaded) return loaded.error();
  ExportReport body;
  Result<Asset> asset = buildJob(job, inputs, &*loaded, &body);
  if (!asset) return asset.error();
  for (Motion& m : loaded->motions) releaseFrames(&m);
  asset->corrective_refit =
      std::make_shared<CorrectiveRefit>();    // no skinning error is measured for a scene
  for (const std::string& note : body.notes)  // file notes repeat on every track: once
    if (std::find(report->notes.begin(), report->notes.end(), note) == report->notes.end())
      report->notes.push_back(note);
  if (report->model_path.empty()) report->model_path = loaded->pick.path;
  if (report->model_note.empty()) report->model_note = loaded->pick.note;
  report->vertices += static_cast<int>(asset->mesh.positions.rows());
  report->joints += static_cast<int>(asset->skeleton.names.size());
  report->morph_targets += static_cast<int>(asset->mesh.morph_targets.size());
  report->max_influences = asset->metadata.max_influences;
  report->options = body.options;
  return asset;
}

Result<ExportReport> runScene(const ExportRequest& r, const RunInputs& inputs, ModelSource* models,
                              Stage* stage) {
  const SteadyTime start = steadyNow();
  const Writer* writer = writerForPath(r.out);
  if (!writer) return usage("no writer for " + r.out);  // checkRequest refused it first
  if (r.clean_temporaries)
    removeStaleTemps(dirName(r.out), {baseName(r.out), baseName(r.out) + ".smpl.json",
                                      baseName(gltfBufferPath(r, r.out))});
  Result<MotionSet> set = sceneTracks(r, stage);
  if (!set) return set.error();
  ExportReport report;
  report.out = r.out;
  report.betas_note = inputs.betas_note;
  // The scene's name, rate and world come from the first track (the tracks move into their bodies).
  const std::string name = set->tracks.front().name;
  const double fps = set->tracks.front().fps;
  const auto world = set->tracks.front().world;
  std::vector<SceneBodyInput> bodies;
  for (Motion& track : set->tracks) {
    stage->set("exporting", r.out, ErrorKind::Export);
    std::vector<bool> detected(track.held.size());
    for (size_t i = 0; i < detected.size(); ++i) detected[i] = !track.held[i];
    const std::string id = track.track;
    Result<Asset> asset = sceneBody(r, inputs, models, stage, std::move(track), &report);
    if (!asset) return asset.error();
    bodies.push_back(SceneBodyInput{std::move(*asset), id, std::move(detected)});
  }
  Result<SceneAsset> scene = composeScene(name, std::move(bodies), fps, set->camera,
                                          worldTurn(r.animation.up, world), r.motions.front());
  if (!scene) return fail(ErrorKind::Load, "loading", r.motions.front(), scene.message());
  for (const std::string& note : scene->notes) report.notes.push_back(note);
  returnFreedHeap();
  const std::string buffer_path = gltfBufferPath(r, r.out);
  Result<size_t> bytes = commitFiles(
      r, buffer_path, writer->serializeSceneFiles(*scene, writerOptionsOf(r, buffer_path)),
      [&](const std::string& producer, const std::vector<FileContent>& contents) {
        return sceneSidecarJson(*scene, producer, contents);
      });
  if (!bytes) return bytes.error();
  std::string ids;
  for (const SceneBody& b : scene->bodies) ids += (ids.empty() ? "" : ", ") + b.asset.name;
  report.notes.push_back("scene: " + std::to_string(scene->bodies.size()) + " bodies (" +
                         printable(ids, 400) + ") on frames " + std::to_string(scene->first_frame) +
                         ".." + std::to_string(scene->end_frame - 1) +
                         (scene->camera.present() ? ", and the camera" : ", no camera"));
  report.bytes = *bytes;
  report.frames = static_cast<int>(scene->end_frame - scene->first_frame);
  report.seconds = secondsSince(start);
  return report;
}

}  // namespace

Result<ExportReport> runSceneExport(const ExportRequest& r, ModelSource* models) {
  if (Status st = beginRun(r); !st) return st.error();
  if (Status st = checkRunPaths(runPaths(r, {r.out}, r.motions)); !st) return usage(st.message());
  Result<RunInputs> inputs = loadRunInputs(r, models);
  if (!inputs) return inputs.error();
  Stage stage;
  stage.set("exporting", r.out, ErrorKind::Export);
  return guarded<ExportReport>(&stage, [&] { return runScene(r, *inputs, models, &stage); });
}

namespace {

// loadRunInputs and, beside it, the producer hash that the commit records:
// the load is serial, and the hash reads the model file a second time on
// the idle core. `job` is `r` with that hash; a hash that fails is left
// unset, and the commit reports its error where it always has.
Result<RunInputs> loadInputsHashed(const ExportRequest& r, ModelSource* models,
                                   ExportRequest* job) {
  *job = r;
  std::optional<Result<RunInputs>> inputs;
  std::optional<Result<std::string>> producer;
  runTogether(
      r.producer_hash.empty() && besideAllowed(r), [&] { inputs = loadRunInputs(r, models); },
      [&] {
        // Off the guarded stage: a throw leaves the hash to the commit,
        // which computes it again under the guard.
        try {
          if (r.producer_hash.empty()) producer = producerOf(r);
        } catch (...) {
          producer.reset();
        }
      });
  if (producer && *producer) job->producer_hash = **producer;
  return std::move(*inputs);
}

}  // namespace

Result<ExportReport> runExportRequest(const ExportRequest& r, ModelSource* models) {
  if (Status st = beginRun(r); !st) return st.error();
  // Before any work: no output may be an input, a directory or a device.
  if (Status st = checkRunPaths(runPaths(r, {r.out}, r.motions)); !st) return usage(st.message());
  ExportRequest job;
  Result<RunInputs> inputs = loadInputsHashed(r, models, &job);
  if (!inputs) return inputs.error();
  return runExportJob(job, *inputs, models);
}

namespace {

// The checks and inputs of runExportRequest, then the job on the caller's
// motions; the path guard only when a file is written.
Result<ExportReport> runDecoded(const ExportRequest& r, std::vector<Motion> motions,
                                ModelSource* models, std::string* memory) {
  if (Status st = beginRun(r); !st) return st.error();
  if (motions.size() > r.motions.size()) return usage("more decoded motions than motion names");
  if (!memory)
    if (Status st = checkRunPaths(runPaths(r, {r.out}, r.motions)); !st) return usage(st.message());
  ExportRequest job = r;  // kept in memory: no sidecar, no producer hash
  Result<RunInputs> inputs = memory ? loadRunInputs(r, models) : loadInputsHashed(r, models, &job);
  if (!inputs) return inputs.error();
  Stage stage;
  stage.set("exporting", r.out, ErrorKind::Export);
  return guarded<ExportReport>(
      &stage, [&] { return runJob(job, *inputs, models, &stage, std::move(motions), memory); });
}

}  // namespace

Result<ExportedBytes> exportToMemory(const ExportRequest& r, std::vector<Motion> motions,
                                     ModelSource* models) {
  if (const WriterFormat* format = writerFormatForPath(r.out);
      format && format->external_buffer && !r.gltf_embed)
    return usage(r.out + ": a .gltf held in memory needs --gltf-embed (its buffer is a file)");
  if (const WriterFormat* format = writerFormatForPath(r.out);
      format && !format->motion_file.empty() && !r.motions.empty())
    return usage(r.out + ": with a motion, " + format->name + " writes <stem>" +
                 format->motion_file + " beside it, which memory cannot hold: give an output path");
  ExportedBytes out;
  Result<ExportReport> report = runDecoded(r, std::move(motions), models, &out.bytes);
  if (!report) return report.error();
  out.report = std::move(*report);
  return out;
}

Result<ExportReport> exportDecoded(const ExportRequest& r, std::vector<Motion> motions,
                                   ModelSource* models) {
  return runDecoded(r, std::move(motions), models, nullptr);
}

}  // namespace smpl
