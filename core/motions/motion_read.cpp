#include "core/motions/motion_read.h"

#include <algorithm>
#include <fstream>

#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/io/npz.h"
#include "core/io/tree/data_tree.h"
#include "core/io/tree/npz_tree.h"
#include "core/memory_budget.h"
#include "core/os/path.h"

namespace smpl {
namespace {

unsigned bitOf(Container c) {
  switch (c) {
    case Container::Npz:
      return kNpzFile;
    case Container::TorchZip:
      return kTorchFile;
    case Container::Pickle:
      return kPickleFile;
    case Container::Joblib:
    case Container::JoblibCompressed:
      return kJoblibFile;
    case Container::Npy:
      return kNpyFile;
    case Container::Json:
      return kJsonFile;
    default:
      return 0;
  }
}

// Member names as None nodes: what a layout's `matches` sees of an .npz.
DataNode namesOf(const std::vector<std::string>& names) {
  DataNode root;
  root.kind = DataNode::Kind::Dict;
  root.keys = names;
  root.children.resize(names.size());
  return root;
}

// The members outside `keys`, with the shapes their headers declare (an
// object member or a bad header: no shape).
std::vector<UndecodedMember> undecodedMembers(const NpzArchive& npz,
                                              const std::vector<std::string>& keys) {
  std::vector<UndecodedMember> out;
  for (const std::string& name : npz.keys()) {
    if (std::find(keys.begin(), keys.end(), name) != keys.end()) continue;
    Result<NpyHeaderInfo> header = npz.header(name);
    out.push_back({name, header ? header->shape : std::vector<int64_t>()});
  }
  return out;
}

// A motion's numbers exist three times while it is read: the decoded member
// (8 bytes per element) and the per-frame rotations built from it (a 3x3
// matrix of doubles, 72 bytes, per 3 axis-angle values: 24 per element). So
// before any member is decoded, the declared sizes of the layout's members are
// checked against the budget with 4 x 8 bytes per element: a file that
// declares two million frames is refused at once, not after gigabytes.
Status checkDeclaredSize(const NpzArchive& npz, const std::vector<std::string>& keys,
                         const std::string& path) {
  double elements = 0;
  std::string largest;
  double largest_count = -1;
  for (const std::string& key : keys) {
    Result<NpyHeaderInfo> header = npz.header(key);
    if (!header || isObjectDescr(header->descr)) continue;  // the decode reports a bad header
    double count = 1;
    for (int64_t d : header->shape) count *= static_cast<double>(d);
    elements += count;
    if (count > largest_count) largest_count = count, largest = key;
  }
  const double bytes = elements * 32.0;
  if (bytes > 1.8e19) return checkMemory(UINT64_MAX, path, "the motion's members");
  return checkMemory(static_cast<uint64_t>(bytes), path,
                     "decoding '" + largest + "' and its frames");
}

Result<MotionFile> readNpz(const std::string& path, bool decode) {
  Result<NpzArchive> npz = NpzArchive::open(path);  // errors name the base name, as the models'
  if (!npz) return npz.error();
  MotionFile file;
  file.container = kNpzFile;
  file.root = namesOf(npz->keys());
  file.layout = findLayout(file.root, kNpzFile);
  if (!decode || !file.layout) return file;
  std::vector<std::string> keys;  // only the layout's keys (NpzArchive is lazy)
  for (const std::string& key : file.layout->keys)
    if (npz->has(key)) keys.push_back(key);
  if (Status st = checkDeclaredSize(*npz, keys, path); !st) return st.error();
  Result<DataNode> tree = readNpzTree(*npz, keys);
  if (!tree) return tree.error();
  file.root = std::move(*tree);
  file.undecoded = undecodedMembers(*npz, file.layout->keys);
  return file;
}

// A binary glTF starts with the magic "glTF" (glTF 2.0 spec, "GLB File Format").
bool isBinaryGltf(const std::string& path) {
  std::ifstream in(os::fsPath(path), std::ios::binary);
  char magic[4] = {};
  return in.read(magic, 4) && std::string(magic, 4) == "glTF";
}

Result<MotionFile> read(const std::string& path, bool decode) {
  // Size bound of what the first bytes show (core/io/input_kind.h), before the
  // file is mapped and walked: a 3 GB pickle or JSON is refused at once.
  if (Result<FileFormat> f = checkInputFile(path, kMotionInput); !f) return f.error();
  Result<Container> container = sniffContainer(path);
  if (!container) return container.error();
  if (*container == Container::Npz) return readNpz(path, decode);
  if (*container == Container::Unknown && isBinaryGltf(path))
    return makeError(path +
                     ": a binary glTF (GLB), an exported scene, not a motion file (a Meshcapade "
                     "scene is JSON text: read PromptHMR's world4d.mcs, not the world4d.glb "
                     "smpl_rs exports)");
  if (*container == Container::Unknown)
    return makeError(path +
                     ": not a motion file (none of .npz, pickle, joblib, torch .pt, .npy, JSON)");
  Result<DataNode> tree = readDataTree(path);
  if (!tree) return tree.error();
  MotionFile file;
  file.container = bitOf(*container);
  file.root = std::move(*tree);
  file.layout = findLayout(file.root, file.container);
  return file;
}

}  // namespace

Result<MotionFile> readMotionFile(const std::string& path) { return read(path, true); }

Result<MotionFile> probeMotionFile(const std::string& path) { return read(path, false); }

}  // namespace smpl
