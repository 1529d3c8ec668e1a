// Batch manifest (--manifest FILE): one JSON object per line and per motion
// of the run (converted, up to date, skipped or failed), sorted by input:
//   {"input":"amass/S1/walk.npz","output":"out/walk.glb","bytes":123456,
//    "sha256":"…","seconds":0.42,"status":"converted"}
// status: "converted" | "up-to-date" | "skipped" (no pose data; output null)
// | "failed" (output null, "error": the error line). bytes and sha256 are the
// output file's (null when there is none); seconds is this run's time for the
// motion. Written atomically at the end of the run. Lines are independent, so
// the manifests of the shards of one batch concatenate (`cat`) into the
// manifest of the whole batch.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

struct ManifestEntry {
  std::string input, output;  // output "" when none
  std::string status;         // converted, up-to-date, skipped, failed
  std::string message;        // failed: the error; skipped: why
  size_t bytes = 0;
  std::string sha256;  // "" when no output
  double seconds = 0.0;
};

// One line, no newline.
std::string manifestLine(const ManifestEntry& entry);

// Sorted by input, one line each, written atomically.
Status writeManifest(const std::string& path, std::vector<ManifestEntry> entries);

}  // namespace smpl
