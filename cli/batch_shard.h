// Deterministic shares of a batch (--shard I/N), so a scheduler (a Slurm job
// array, a Kubernetes indexed Job, GNU parallel over ssh) can spread one
// --motion-dir run over machines with no coordination:
//   the motions are sorted by their path relative to the motion folder
//   ('/'-separated, byte order), and the one at position p (0-based) belongs
//   to shard p mod N.
// Every motion is in exactly one shard; shard sizes differ by at most one.
// The rule depends only on the file list, so all shards agree on it as long
// as they see the same folder.
#pragma once

#include <string>
#include <vector>

namespace smpl {

// Share `index` of `count` (0 <= index < count) of `files` (paths under
// `root`), in the sorted order above.
std::vector<std::string> shardMotions(std::vector<std::string> files, const std::string& root,
                                      int index, int count);

}  // namespace smpl
