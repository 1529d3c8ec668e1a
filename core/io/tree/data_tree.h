// One entry point for the containers motion files come in, each read as a
// DataNode tree (core/data_node.h) by a data-only reader: nothing in a file is
// ever executed. Which container a file is comes from its bytes, never its
// name (WHAM's joblib output is called .pkl, GVHMR's torch file .pt):
//   Npz               zip of .npy members (np.savez), lazy: readNpzTree
//   TorchZip          zip with a <name>/data.pkl record (torch.save, torch >= 1.6)
//   Pickle            a plain pickle (protocols 0-5)
//   Joblib            an uncompressed joblib.dump (a pickle naming
//                     joblib.numpy_pickle's array wrapper)
//   JoblibCompressed  joblib.dump(..., compress=...): zlib and gzip are read,
//                     bz2/lzma/xz/lz4 refused by name when read
//   Npy               .npy (numeric, text, or object: np.save of a dict)
//   Json              JSON text ('{' or '[' first, after whitespace/BOM)
//   Unknown           none of these
// The readers behind it: core/io/pickle/pickle_tree.h (pickle, joblib, torch,
// .npy), core/io/tree/npz_tree.h, core/io/tree/json_tree.h.
//
//   Result<DataNode> tree = readDataTree("wham_output.pkl");
//   const DataNode* track = tree->get("0");             // track id 0
//   const Array* pose = track ? track->leaf("pose") : nullptr;   // (T,72)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/data_node.h"
#include "core/result.h"

namespace smpl {

enum class Container { Npz, TorchZip, Pickle, Joblib, JoblibCompressed, Npy, Json, Unknown };

// "npz archive", "torch archive", "pickle", "joblib file", "compressed joblib
// file", "npy file", "JSON file", "unknown": for messages.
const char* containerName(Container container);

// From the first bytes (for a zip: its member names, without extracting any;
// for a pickle: whether it names joblib's array wrapper). Errors: the file
// cannot be read, a zip whose directory is corrupt, and two formats we
// recognise but never read: torch's legacy serialization ("a legacy torch
// file: re-save it with torch.save(obj, f) in torch >= 1.6") and joblib's
// pre-0.9.3 zfile.
Result<Container> sniffContainer(const std::string& path);
Result<Container> sniffContainer(const uint8_t* data, size_t size, const std::string& context);

// An .npz's member names without ".npy", in archive order; nothing is
// decoded. Other containers: an error ("x.pt: a torch archive, not an .npz:
// read it with readDataTree").
Result<std::vector<std::string>> containerKeys(const std::string& path);

// The file as a tree. Npz: a Dict of only the members `npz_keys` names
// (absent ones left out; all members when empty); every other container:
// the whole file (`npz_keys` unused). Errors name the file (and the member,
// key path or byte offset where known), e.g.
//   "wham_output.pkl: refusing pickle global 'os.system' (not model data)"
//   "x.pkl: a bz2-compressed joblib file: decompress it first (...)"
//   "hmr4d_results.pt: no record 'hmr4d_results/data/3' for storage key '3'"
Result<DataNode> readDataTree(const std::string& path,
                              const std::vector<std::string>& npz_keys = {});
// The same over bytes in memory (tests, fuzzing); `context` names them.
Result<DataNode> readDataTree(const uint8_t* data, size_t size, const std::string& context,
                              const std::vector<std::string>& npz_keys = {});

}  // namespace smpl
