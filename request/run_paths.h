// Every path a run reads or writes, in one list, and the
// guard that checks that list before any work. Inputs are never overwritten:
// two paths are the same file when their real paths match (symbolic links
// resolved) or they have the same device and inode (hard links). The loaders
// recognise files by content, so without this `--model m.glb --out m.glb`
// would replace the model.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"
#include "request/export_request.h"

namespace smpl {

struct RunPaths {
  // The model (a file; for a folder each file core/models/model_folder.h may
  // pick, two levels deep; not "builtin"), every motion, --betas-file, --uv
  // (and its numpy partner, core/models/uv_npy.h), --dmpl (a file; for a folder
  // each basis core/models/dmpl.h findDmplBasis may pick).
  std::vector<std::string> inputs;
  // Each output, its sidecar "<out>.smpl.json", the buffer "<stem>.bin" of a
  // .gltf (unless --gltf-embed), and the batch --manifest.
  std::vector<std::string> outputs;
  std::string manifest;    // --manifest ("" = none), also in `outputs`
  std::string motion_dir;  // --motion-dir ("" = not a batch)
};

// The paths of a run of `request` writing `outs` from `motions` (one export:
// {request.out} and request.motions; a batch: every planned output and every
// motion listed in the folder).
RunPaths runPaths(const ExportRequest& request, const std::vector<std::string>& outs,
                  const std::vector<std::string>& motions);

// The external buffer file written beside an output whose writer row has
// one (writers/writer.h external_buffer: DIR/body.gltf -> DIR/body.bin; with
// a motion, motion_file: DIR/body.xml -> DIR/body.qpos.npz), or "" (GLB, FBX,
// --gltf-embed, an MJCF file without a motion).
std::string gltfBufferPath(const ExportRequest& request, const std::string& out);

// The guard, one line naming both paths (kind Usage, exit 1; no prefix):
//   an output is an input:  "output out.glb would overwrite the input model.glb (same file);
//                            choose another output path"
//   an output exists and is not a regular file (a directory, a device such as /dev/full):
//                           "output /dev/full is a character device, not a file; choose
//                            another output path"
//   two outputs are one file (--manifest = an output):
//                           "outputs o/walk.glb and o/walk.glb (--manifest) are the same file;
//                            choose another path"
//   the manifest is directly in the motion folder (the next run would list it):
//                           "--manifest m/x.json is in the --motion-dir folder m; ..."
// Outputs that do not exist yet cannot clash with inputs and pass.
Status checkRunPaths(const RunPaths& paths);

}  // namespace smpl
