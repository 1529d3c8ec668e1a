#include "request/input_role.h"

#include <filesystem>
#include <fstream>

#include "core/motions/motion_layout.h"
#include "core/motions/motion_read.h"
#include "core/os/path.h"

namespace smpl {
namespace {

const char* kModelHint =
    "--model takes the model authors' .npz or .pkl (SMPL_NEUTRAL.npz, SMPLH_NEUTRAL.npz, "
    "SMPLX_NEUTRAL.npz, MANO_RIGHT.pkl) or a folder of them";

// A binary glTF starts with the magic "glTF" (glTF 2.0 spec, "GLB File Format").
bool startsWithGlbMagic(const std::string& path) {
  std::ifstream in(os::fsPath(path), std::ios::binary);
  char magic[4] = {};
  return in.read(magic, 4) && std::string(magic, 4) == "glTF";
}

}  // namespace

Error modelRoleError(const std::string& path, const Error& refused) {
  // Only a regular file is opened again: a FIFO or a terminal given as
  // --model must not block here after the loader refused it.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(os::fsPath(path), ec)) return refused;
  if (startsWithGlbMagic(path))
    return makeError(
        path + ": a binary glTF (GLB), an exported file, not a body model; " + kModelHint,
        refused.kind);
  Result<MotionFile> file = probeMotionFile(path);
  if (!file) return refused;
  if (file->layout)
    return makeError(path + ": a motion file (the " + file->layout->name +
                         " layout), not a body model: give it as --motion; " + kModelHint,
                     refused.kind);
  if (isShapeOnly(file->root))
    return makeError(
        path + ": a shape file (betas only), not a body model: give it as --betas-file; " +
            kModelHint,
        refused.kind);
  return refused;
}

}  // namespace smpl
