// Inputs are never overwritten: before any work, every planned output (and
// its sidecar) is compared with every input file of the run. Two paths are the
// same file when their real paths match (symbolic links resolved) or when they
// have the same device and inode (hard links). The loaders recognise files by
// content, so without this `--model m.glb --out m.glb` would replace the model.
#pragma once

#include <string>
#include <vector>

#include "cli/settings.h"
#include "core/result.h"

namespace smpl {

// The input files of a run: the model (unless "builtin"), --betas-file, --uv,
// and `motions`. A folder given as an input (a --model folder) stands for the
// regular files directly in it.
std::vector<std::string> runInputs(const Settings& settings,
                                   const std::vector<std::string>& motions);

// The external buffer file written beside a .gltf output (DIR/body.gltf ->
// DIR/body.bin), or "" (GLB, FBX, or --gltf-embed).
std::string gltfBufferPath(const Settings& settings, const std::string& out);

// The files an export to `out` writes besides its sidecar: `out` and, for a
// .gltf, its buffer file.
std::vector<std::string> outputsOf(const Settings& settings, const std::string& out);

// Error (one line, both paths named) when an output or its sidecar
// "<output>.smpl.json" is one of `inputs`:
//   "output out.glb would overwrite the input model.glb (same file); choose another output path"
// Outputs that do not exist yet cannot clash and pass.
Status checkOutputsAreNotInputs(const std::vector<std::string>& outputs,
                                const std::vector<std::string>& inputs);

}  // namespace smpl
