// What one export is asked to do, as plain data: every input, output and
// option, each field named after the smpl-export option it comes from
// (docs/cli.md). The command line (cli/) and the developer tools
// (tools/reference) fill one; the request layer checks it once
// (check_request.h), loads the inputs (each motion decoded once), builds the
// asset (exportAsset) and writes the output with its sidecar
// (run_request.h). Nothing here knows about argv.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/math/skin_weights.h"
#include "core/motions/motion.h"
#include "core/motions/motion_tracks.h"
#include "exporter/animation.h"
#include "exporter/export_options.h"
#include "exporter/pruning_error.h"
#include "writers/writer.h"

namespace smpl {

struct ExportRequest {
  // --- inputs ---
  std::string model;                 // --model PATH|DIR|builtin (file, folder picked per motion)
  std::vector<std::string> motions;  // --motion FILE, one animation each (batch: the job's motion);
                                     // --motion-sequence DIR is one of them too
  std::string motion_sequence;  // --motion-sequence DIR: per-frame files joined (motion_sequence.h)
  TrackChoice track;            // --track ID|longest|all (core/motions/motion_tracks.h)
  // How the motion files are read (core/motions/motion.h): source_fps
  // --source-fps R in [1, 1000]; source_params --source-params global|incam;
  // skip_bad_frames --skip-bad-frames; max_held_frames --max-held-frames N,
  // 0..kMaxHeldFramesLimit per gap. up_given and frame_file are set by the
  // run (request_motions.h).
  MotionOptions reading;
  bool scene = false;                  // --scene: every track a body of one file (run_request.h)
  bool flat_hand_mean = false;         // --flat-hand-mean: fit hands are flat-hand relative
  std::vector<std::string> hands;      // --hands FILE|DIR, at most 2: MANO tracks, the fingers
  bool hands_wrist = false;            // --hands-wrist: the wrists from the hand tracks too
  std::string betas_file;              // --betas-file FILE: .npy, .npz (key 'betas') or .json
  bool betas_from_motion = false;      // --betas-from-motion: the first motion must carry betas
  std::string dmpl;                    // --dmpl FILE|DIR: DMPL basis (DIR: per motion gender)
  std::optional<int> dmpl_count;       // --dmpl-count N >= 1: the first N directions (none: all)
  bool dmpl_regressed_joints = false;  // --dmpl-joints regressed (false: fixed)

  // --- the asset, as exportAsset takes it (exporter/export_options.h) ---
  //   betas            --betas v,v,...: |v| <= 1000, at most the model's B; the run
  //                    replaces them with the betas it resolved (file, motion)
  //   expression       --expression v,v,...: SMPL-X, |v| <= 1000
  //   max_influences   --max-influences N|all: 1..K, or kAllInfluences
  //   skin_weights     --skin-weights; correctives --correctives all|none;
  //   corrective_refit --corrective-refit on|off; encoding --corrective-weights;
  //   corrective_basis --corrective-basis K; shape_keys --shape-keys N;
  //   expression_keys  --expression-keys N; uv_obj --uv OBJ|NPY|none; name --name;
  //   quantize_morphs  --quantize-morphs; origin --origin; root_bone --root-bone
  //   mesh             set by the run from the output's writer row (needs_mesh)
  ExportOptions asset;

  // --- the bake (exporter/animation.h) ---
  //   fps --fps F in (0, 1000]; first_frame, end_frame --frames A:B;
  //   up --up y|z; in_place --root-motion in-place
  AnimationOptions animation;

  // --- the writer (writers/writer.h) ---
  //   morph_epsilon --corrective-epsilon M in [0, 0.01] m; draco, meshopt,
  //   quantize_animation; fbx_units, fbx_version, fbx_compress_level;
  //   bvh_units; density, mjcf_joints, mjcf_geoms, mjcf_motors; threads --threads N,
  //   1..1024 (none: all cores). binary and buffer_uri are set by the run
  //   from the output's path (request_options.h writerOptionsOf).
  WriterOptions writer;
  bool gltf_embed = false;  // --gltf-embed: .gltf buffer as a data URI (else FILE.bin)

  // --- the run ---
  std::string out;     // --out FILE: .glb, .gltf, .fbx or .bvh (batch: the job's output)
  std::string format;  // --format (batch): the outputs' writer row name ("" = the table's first)
  std::string motion_dir;     // --motion-dir DIR (batch): read by the path guard (run_paths.h)
  std::string manifest;       // --manifest FILE (batch): an output of the run for the guard
  uint64_t memory_limit = 0;  // --memory-limit, bytes (0 = defaultMemoryLimit())
  // (name, value) of each option that changes the bytes written, as given;
  // the producer hash (producer.h) sorts and hashes them.
  std::vector<std::pair<std::string, std::string>> hashed_options;
  std::string producer_hash;      // recorded in the sidecar; "" = computed (producer.h)
  bool clean_temporaries = true;  // remove stale temporaries of `out` first (a batch did)
  int skin_error_poses = 0;       // > 0: measure the held-out skinning error (summary line)
  // Called while each motion bakes (motion name, fraction in [0, 1]); may be empty.
  std::function<void(const std::string&, double)> progress;
};

// What one export did, for the summary (cli/summary.h) and the batch lines.
// Wall time of one export's stages, in seconds: reading (the motions decoded,
// the model picked), the fit and the bake (exporter/export_asset.h
// ExportTimes) and writing (serialising and committing the files). Their sum
// is at most ExportReport::seconds.
struct StageSeconds {
  double read = 0.0, fit = 0.0, bake = 0.0, write = 0.0;
};

struct ExportReport {
  std::string out;       // the output written (with --track all: <stem>.track<ID>.<ext>)
  size_t bytes = 0;      // output plus external buffer
  double seconds = 0.0;  // wall time of the export (not of the skinning error)
  StageSeconds stages;   // where `seconds` went
  int vertices = 0, joints = 0, morph_targets = 0, max_influences = 0;
  int frames = 0;                  // total animation frames written
  std::vector<std::string> notes;  // motion notes, dropped joints, DMPL, ..., in order
  std::string betas_note;          // "<betas file>: <rows averaged ...>" or ""
  std::string model_path;          // the model file used ("builtin"; a folder's pick)
  std::string model_note;          // why a folder's pick is not the wanted gender, or ""
  ExportOptions options;           // as used (betas may come from the motion or the file)
  bool skin_fitted = false;        // a skin was built (fitted or truncated); not for a writer
                                   // without a mesh (writers/writer.h needs_mesh)
  SparseSkin skin;  // the skin written, per model vertex (exporter/pruning_error.h skinOfAsset)
  bool skin_error_measured = false;  // request.skin_error_poses > 0 and skin_fitted
  PruningError skin_error;
  Placement placement;  // --origin / --root-bone as applied (the floor offset)
};

}  // namespace smpl
