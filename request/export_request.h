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

namespace smpl {

struct ExportRequest {
  // --- inputs ---
  std::string model;                 // --model PATH|DIR|builtin (file, folder picked per motion)
  std::vector<std::string> motions;  // --motion FILE, one animation each (batch: the job's motion);
                                     // --motion-sequence DIR is one of them too
  std::string motion_sequence;  // --motion-sequence DIR: per-frame files joined (motion_sequence.h)
  TrackChoice track;            // --track ID|longest|all (core/motions/motion_tracks.h)
  bool skip_bad_frames = false;    // --skip-bad-frames: folders of frames skip unreadable entries
  int64_t max_held_frames = 1000;  // --max-held-frames N: 0..kMaxHeldFramesLimit per gap
  bool scene = false;              // --scene: every track a body of one file (run_request.h)
  SourceParams source_params = SourceParams::Default;  // --source-params global|incam
  std::optional<double> source_fps;    // --source-fps R, fps in [1, 1000]; none: the stored rate
  bool flat_hand_mean = false;         // --flat-hand-mean: fit hands are flat-hand relative
  std::vector<std::string> hands;      // --hands FILE|DIR, at most 2: MANO tracks, the fingers
  bool hands_wrist = false;            // --hands-wrist: the wrists from the hand tracks too
  std::vector<double> betas;           // --betas v,v,...: |v| <= 1000, at most the model's B
  std::string betas_file;              // --betas-file FILE: .npy, .npz (key 'betas') or .json
  bool betas_from_motion = false;      // --betas-from-motion: the first motion must carry betas
  std::vector<double> expression;      // --expression v,v,...: SMPL-X, |v| <= 1000
  std::string uv;                      // --uv OBJ|NPY|none ("" = the model file's own vt/ft)
  std::string dmpl;                    // --dmpl FILE|DIR: DMPL basis (DIR: per motion gender)
  std::optional<int> dmpl_count;       // --dmpl-count N >= 1: the first N directions (none: all)
  bool dmpl_regressed_joints = false;  // --dmpl-joints regressed (false: fixed)

  // --- the asset (ExportOptions) ---
  int max_influences = 4;       // --max-influences N: 1..K (the model's joints)
  bool all_influences = false;  // --max-influences all: as many as the model's vertices use
  SkinWeightMethod skin_weights = SkinWeightMethod::Optimized;  // --skin-weights
  bool correctives = true;                                      // --correctives all|none
  bool corrective_refit = true;  // --corrective-refit on|off (core/math/corrective_refit.h)
  CorrectiveEncoding encoding = CorrectiveEncoding::Auto;  // --corrective-weights
  int corrective_basis = 0;      // --corrective-basis K: 1..P principal components (0 = none)
  int shape_keys = 0;            // --shape-keys N: 0..B shape_<i> targets
  int expression_keys = 0;       // --expression-keys N: 0..E expr_<i> targets
  std::string name = "body";     // --name NAME: the mesh name
  std::optional<Origin> origin;  // --origin model|floor (none: model, or floor with --root-bone)
  bool root_bone = false;        // --root-bone: a `root` joint on the floor (implies floor)

  // --- animation (AnimationOptions) ---
  std::optional<double> fps;  // --fps F: output rate in (0, 1000] fps; none: each motion's rate
  int first_frame = 0;        // --frames A:B, A >= 0 (source frames, before resampling)
  int end_frame = -1;         // --frames A:B, B > A exclusive; -1: to the end
  UpAxis up = UpAxis::Auto;   // --up y|z (Auto: z for AMASS files, else y)
  bool in_place = false;      // --root-motion in-place

  // --- the writer (WriterOptions) ---
  double corrective_epsilon = 0.0;    // --corrective-epsilon M: metres in [0, 0.01] (glTF)
  bool quantize_morphs = false;       // --quantize-morphs (glTF int16 deltas)
  bool draco = false;                 // --draco (glTF)
  bool meshopt = false;               // --meshopt (glTF): EXT_meshopt_compression
  bool quantize_animation = false;    // --quantize-animation (glTF): normalised int16 keys
  bool gltf_embed = false;            // --gltf-embed: .gltf buffer as a data URI (else FILE.bin)
  std::string fbx_units = "m";        // --fbx-units m|cm
  int fbx_version = 7400;             // --fbx-version 7400|7500
  int fbx_compress_level = 1;         // --fbx-compress-level N: 0..12
  std::string bvh_units = "m";        // --bvh-units m|cm
  double density = 1000.0;            // --density KG_M3: (0, 1e5] kg/m^3 (MJCF body masses)
  std::string mjcf_joints = "hinge";  // --mjcf-joints hinge|ball
  bool mjcf_motors = false;           // --mjcf-motors: a motor per hinge (MJCF)

  // --- the run ---
  std::string out;     // --out FILE: .glb, .gltf, .fbx or .bvh (batch: the job's output)
  std::string format;  // --format (batch): the outputs' writer row name ("" = the table's first)
  std::string motion_dir;      // --motion-dir DIR (batch): read by the path guard (run_paths.h)
  std::string manifest;        // --manifest FILE (batch): an output of the run for the guard
  std::optional<int> threads;  // --threads N, 1..1024 (none: all cores): this export's FBX workers
  uint64_t memory_limit = 0;   // --memory-limit, bytes (0 = defaultMemoryLimit())
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
struct ExportReport {
  std::string out;       // the output written (with --track all: <stem>.track<ID>.<ext>)
  size_t bytes = 0;      // output plus external buffer
  double seconds = 0.0;  // wall time of the export (not of the skinning error)
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
