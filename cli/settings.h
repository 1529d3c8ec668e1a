// Command-line settings of smpl-export, parsed and checked before any work
// (gltfpack's discipline: unknown or conflicting options fail first). The
// options themselves are described once, in cli/options.h.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/result.h"
#include "exporter/animation.h"
#include "exporter/pipeline.h"
#include "plugins/writer.h"

namespace smpl {

struct Settings {
  std::string model;  // path or "builtin"
  std::string out;
  std::string betas_file;
  std::vector<std::string> motions;  // --motion, repeatable: one animation each
  std::string motion_dir, out_dir;   // batch mode
  std::string format = "glb";        // batch output format
  AnimationOptions animation;
  bool betas_given = false;        // --betas or --betas-file; else betas come from the motion
  bool betas_from_motion = false;  // --betas-from-motion: the motion must carry betas
  ExportOptions export_options;
  WriterOptions writer_options;
  bool gltf_embed =
      false;  // --gltf-embed: .gltf with the buffer as a data URI (else FILE.bin beside it)
  bool quiet = false;
  bool help = false;
  bool version = false;
  int error_poses = 32;       // random poses for the pruning-error report
  int threads = 0;            // batch workers; 0 = all cores
  uint64_t memory_limit = 0;  // --memory-limit in bytes; 0 = defaultMemoryLimit()
  bool force = false;         // batch: rebuild outputs even when up to date
  std::vector<std::pair<std::string, std::string>>
      given_options;  // (name, value) as given; producer hash
  double source_fps =
      0.0;  // --source-fps: rate of the motion files (0: stored, else assumed with a note)
  bool flat_hand_mean = false;           // --flat-hand-mean: fit hand poses are flat-hand relative
  int shard_index = 0, shard_count = 1;  // --shard I/N (batch): this run's share
  std::string manifest;  // --manifest FILE (batch): JSON-lines record of every motion
  std::string
      dmpl;  // --dmpl FILE|DIR: DMPL soft-tissue basis (DIR: per motion gender, core/load/dmpl.h)
  int dmpl_count = 0;  // --dmpl-count N: keep the first N directions (0 = all)
  bool dmpl_regressed_joints =
      false;  // --dmpl-joints regressed: animate joint translations (published math)
};

// Parse argv through the option table, then check the rules between options.
// Errors are one line for the user, of kind Usage (exit 1).
Result<Settings> parseSettings(int argc, const char* const* argv);

}  // namespace smpl
