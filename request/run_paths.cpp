// runPaths / checkRunPaths: stat every input once (dev, inode, real path),
// then look every output up. Uses the error_code overloads of
// std::filesystem: an input that cannot be resolved is left to its loader.
#include "request/run_paths.h"

#include <filesystem>
#include <map>
#include <utility>

#include "core/io/file_io.h"
#include "core/models/model_folder.h"
#include "core/models/uv_npy.h"
#include "core/os/files.h"
#include "core/os/path.h"
#include "writers/writer.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

using FileKey = std::pair<uint64_t, uint64_t>;  // (device, inode)

struct Identity {
  os::FileIdentity file;
  std::string real;  // fs::canonical
};

bool identify(const std::string& path, Identity* id) {
  if (!os::identify(path, &id->file)) return false;  // follows symlinks
  std::error_code ec;
  const fs::path real = fs::canonical(os::fsPath(path), ec);
  id->real = ec ? std::string() : os::utf8(real);
  return true;
}

bool isDirectory(const std::string& path) {
  std::error_code ec;
  return !path.empty() && fs::is_directory(os::fsPath(path), ec);
}

// Each file of a model folder a pick may choose (core/models/model_folder.h).
void addModelFolder(const std::string& dir, std::vector<std::string>* files) {
  for (const std::string& rel : listModelFolder(dir))
    files->push_back(os::utf8(os::fsPath(dir) / os::fsPath(rel)));
}

// Each basis findDmplBasis (core/models/dmpl.h) may pick from a --dmpl folder.
void addDmplFolder(const std::string& dir, std::vector<std::string>* files) {
  for (const char* sub : {"dmpls/", ""})
    for (const char* gender : {"female", "male", "neutral"})
      files->push_back(dir + "/" + sub + gender + "/model.npz");
}

void addUv(const std::string& uv, std::vector<std::string>* files) {
  if (uv.empty() || uv == "none") return;
  files->push_back(uv);
  Result<std::pair<std::string, std::string>> pair = uvNumpyPairPaths(uv);  // the partner .npy
  if (pair) files->push_back(pair->first == uv ? pair->second : pair->first);
}

const char* kindOf(os::FileType type) {
  switch (type) {
    case os::FileType::Directory:
      return "a directory";
    case os::FileType::CharDevice:
      return "a character device";
    case os::FileType::BlockDevice:
      return "a block device";
    case os::FileType::Pipe:
      return "a named pipe";
    case os::FileType::Socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

// One output against the inputs' identities.
Status checkOutput(const std::string& out, const std::map<FileKey, std::string>& by_inode,
                   const std::map<std::string, std::string>& by_path) {
  Identity id;
  if (!identify(out, &id)) return Status();  // not there yet: cannot clash
  auto inode = by_inode.find({id.file.device, id.file.inode});
  auto real = by_path.find(id.real);
  const std::string* input = inode != by_inode.end() ? &inode->second
                             : real != by_path.end() ? &real->second
                                                     : nullptr;
  if (input)
    return makeError("output " + out + " would overwrite the input " + *input +
                         " (same file); choose another output path",
                     ErrorKind::Usage);
  if (id.file.type != os::FileType::Regular)
    return makeError("output " + out + " is " + kindOf(id.file.type) +
                         ", not a file; choose another output path",
                     ErrorKind::Usage);
  return Status();
}

// The file an output path names: its absolute path with the links of its
// existing part resolved (the same key whether the file exists yet or not).
std::string outputKey(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(os::fsPath(path), ec), ec);
  return ec ? path : os::utf8(p);
}

Status checkOutputsDistinct(const RunPaths& paths) {
  std::map<std::string, std::string> seen;
  for (const std::string& out : paths.outputs) {
    auto [it, fresh] = seen.emplace(outputKey(out), out);
    if (fresh) continue;
    const bool manifest = !paths.manifest.empty() && out == paths.manifest;
    return makeError("outputs " + it->second + " and " + out + (manifest ? " (--manifest)" : "") +
                         " are the same file; choose another path",
                     ErrorKind::Usage);
  }
  return Status();
}

Status checkManifestFolder(const RunPaths& paths) {
  if (paths.manifest.empty() || paths.motion_dir.empty()) return Status();
  Identity folder, parent;
  if (!identify(paths.motion_dir, &folder) || !identify(dirName(paths.manifest), &parent))
    return Status();
  if (folder.file.device != parent.file.device || folder.file.inode != parent.file.inode)
    return Status();
  return makeError("--manifest " + paths.manifest + " is in the --motion-dir folder " +
                       paths.motion_dir +
                       " (the next run would read it as a motion); choose another folder",
                   ErrorKind::Usage);
}

}  // namespace

RunPaths runPaths(const ExportRequest& r, const std::vector<std::string>& outs,
                  const std::vector<std::string>& motions) {
  RunPaths paths;
  paths.inputs = motions;
  paths.inputs.insert(paths.inputs.end(), r.hands.begin(), r.hands.end());
  if (r.model != "builtin" && isDirectory(r.model))
    addModelFolder(r.model, &paths.inputs);
  else if (r.model != "builtin")
    paths.inputs.push_back(r.model);
  paths.inputs.push_back(r.betas_file);
  addUv(r.asset.uv_obj, &paths.inputs);
  if (isDirectory(r.dmpl))
    addDmplFolder(r.dmpl, &paths.inputs);
  else
    paths.inputs.push_back(r.dmpl);
  for (const std::string& out : outs) {
    paths.outputs.push_back(out);
    paths.outputs.push_back(out + ".smpl.json");
    if (std::string buffer = gltfBufferPath(r, out); !buffer.empty())
      paths.outputs.push_back(buffer);
  }
  if (!r.manifest.empty()) paths.outputs.push_back(r.manifest);
  paths.manifest = r.manifest;
  paths.motion_dir = r.motion_dir;
  return paths;
}

std::string gltfBufferPath(const ExportRequest& r, const std::string& out) {
  const WriterFormat* format = writerFormatForPath(out);
  const size_t dot = out.rfind('.');  // the row's extension, whatever its case
  if (format && !format->motion_file.empty() && (!r.motions.empty() || !r.motion_dir.empty()))
    return out.substr(0, dot) + format->motion_file;  // MJCF: <stem>.qpos.npz
  if (r.gltf_embed || !format || !format->external_buffer) return "";
  return out.substr(0, dot) + ".bin";
}

Status checkRunPaths(const RunPaths& paths) {
  std::map<FileKey, std::string> by_inode;
  std::map<std::string, std::string> by_path;
  for (const std::string& in : paths.inputs) {
    Identity id;
    if (!identify(in, &id)) continue;
    by_inode.emplace(std::make_pair(id.file.device, id.file.inode), in);
    if (!id.real.empty()) by_path.emplace(id.real, in);
  }
  for (const std::string& out : paths.outputs)
    if (Status st = checkOutput(out, by_inode, by_path); !st) return st;
  if (Status st = checkOutputsDistinct(paths); !st) return st;
  return checkManifestFolder(paths);
}

}  // namespace smpl
