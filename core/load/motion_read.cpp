#include "core/load/motion_read.h"

#include "core/io/file_io.h"
#include "core/io/npz.h"
#include "core/io/tree/data_tree.h"
#include "core/io/tree/npz_tree.h"

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
  Result<DataNode> tree = readNpzTree(*npz, keys);
  if (!tree) return tree.error();
  file.root = std::move(*tree);
  return file;
}

Result<MotionFile> read(const std::string& path, bool decode) {
  // Size bound of what the first bytes show (core/io/input_kind.h), before the
  // file is mapped and walked: a 3 GB pickle or JSON is refused at once.
  if (Result<FileFormat> f = checkInputFile(path, kMotionInput); !f) return f.error();
  Result<Container> container = sniffContainer(path);
  if (!container) return container.error();
  if (*container == Container::Npz) return readNpz(path, decode);
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
