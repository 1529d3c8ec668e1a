// Batch planning (--motion-dir DIR --out-dir DIR), done before any work:
// list the motions, map each to its output, refuse name collisions, run the
// path guard over every path of the run (request/run_paths.h:
// outputs that are inputs, directories or devices, the manifest), remove
// stale temporaries of these outputs, and decide which outputs are up to date. runBatch (batch.h)
// then converts.
//
// Rules (README "Batch mode"):
// - DIR missing or not a folder: error naming it, exit 2.
// - Motions are the regular files named *.npz / *.json / *.smpl / *.pkl (not
//   our sidecars *.smpl.json) directly in DIR; subfolders are not entered, so a symbolic
//   link loop cannot recurse. A motion-named entry that cannot be examined
//   (symbolic link loop, dangling link, permission) is an error line of its
//   own (counted as failed); a motion-named entry that is not a regular file
//   (a folder, a FIFO) is a note and skipped.
// - Two motions mapping to one output (walk.npz and walk.json -> walk.glb):
//   the run is refused before any work, exit 1, naming both.
// - Up to date: the output and its sidecar exist, are not older than the
//   motion, the sidecar's producer hash (producer.h) equals this run's, and
//   every file of the output (a .gltf's .bin too) has the size and SHA-256 the
//   sidecar records (a truncated or replaced output is rebuilt); --force
//   rebuilds everything.
// - --shard I/N keeps share I after the collision check (which sees every
//   motion, so shards cannot collide with each other): cli/batch_shard.h.
#pragma once

#include <string>
#include <vector>

#include "cli/settings.h"
#include "core/result.h"

namespace smpl {

struct PlannedOutput {
  std::string motion;         // DIR/walk.npz
  std::string out;            // OUT/walk.glb
  std::string producer_hash;  // recorded in OUT/walk.glb.smpl.json
  bool up_to_date = false;
};

struct BatchPlan {
  std::vector<PlannedOutput> outputs;  // sorted by motion path
  std::vector<std::string> errors;     // "Error loading DIR/x.npz: ..." per unreadable entry
  std::vector<std::string> notes;      // "DIR/x.npz: not a regular file; skipped"
  size_t listed = 0;                   // motions in DIR before --shard kept this run's share
};

// The plan, or an error (one line for the user; its kind gives the exit
// code) when the run must not start.
Result<BatchPlan> planBatch(const Settings& settings);

}  // namespace smpl
