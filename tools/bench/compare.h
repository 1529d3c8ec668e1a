// smpl-bench --compare: this project's numbers beside the peers that run on
// this machine, in one run, as ratios (README "Benchmarks: side by side").
#pragma once

#include <string>

namespace smpl {

struct CompareOptions {
  std::string smplx;    // checkout of github.com/vchoutas/smplx; empty: row says "absent"
  std::string standin;  // folder for the full-size stand-in files (made on first use)
  std::string blender = "blender";
  int frames = 1024;  // forward-pass frames (both sides)
  int batch = 64;     // frames per batched call (both sides)
};

// Prints the table to stdout; returns a process exit code (0, or 1 when the
// stand-in cannot be made or loaded). A peer that cannot run gets a row that
// says why, never a silent omission.
int runCompare(const CompareOptions& options);

}  // namespace smpl
