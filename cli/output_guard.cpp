// checkOutputsAreNotInputs: stat every input once (dev, inode, real path),
// then look every output up. Uses the error_code overloads of
// std::filesystem: an input that cannot be resolved is left to its loader.
#include "cli/output_guard.h"

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <utility>

namespace smpl {
namespace fs = std::filesystem;
namespace {

struct Identity {
  dev_t dev;
  ino_t ino;
  std::string real;  // fs::canonical
};

bool identify(const std::string& path, Identity* id) {
  struct stat st;
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return false;  // follows symlinks
  std::error_code ec;
  const fs::path real = fs::canonical(path, ec);
  *id = Identity{st.st_dev, st.st_ino, ec ? std::string() : real.string()};
  return true;
}

void addFolderFiles(const std::string& dir, std::vector<std::string>* files) {
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    std::error_code e2;
    if (it->is_regular_file(e2)) files->push_back(it->path().string());
  }
}

}  // namespace

std::vector<std::string> runInputs(const Settings& s, const std::vector<std::string>& motions) {
  std::vector<std::string> candidates = motions;
  if (s.model != "builtin") candidates.push_back(s.model);
  candidates.push_back(s.betas_file);
  candidates.push_back(s.export_options.uv_obj);
  std::vector<std::string> inputs;
  for (const std::string& c : candidates) {
    std::error_code ec;
    if (c.empty()) continue;
    if (fs::is_directory(c, ec))
      addFolderFiles(c, &inputs);
    else
      inputs.push_back(c);
  }
  return inputs;
}

std::string gltfBufferPath(const Settings& s, const std::string& out) {
  const size_t dot = out.rfind('.');
  if (s.gltf_embed || dot == std::string::npos || out.compare(dot, std::string::npos, ".gltf") != 0)
    return "";
  return out.substr(0, dot) + ".bin";
}

std::vector<std::string> outputsOf(const Settings& s, const std::string& out) {
  const std::string buffer = gltfBufferPath(s, out);
  if (buffer.empty()) return {out};
  return {out, buffer};
}

Status checkOutputsAreNotInputs(const std::vector<std::string>& outputs,
                                const std::vector<std::string>& inputs) {
  std::map<std::pair<dev_t, ino_t>, std::string> by_inode;
  std::map<std::string, std::string> by_path;
  for (const std::string& in : inputs) {
    Identity id;
    if (!identify(in, &id)) continue;
    by_inode.emplace(std::make_pair(id.dev, id.ino), in);
    if (!id.real.empty()) by_path.emplace(id.real, in);
  }
  for (const std::string& out : outputs) {
    for (const std::string& path : {out, out + ".smpl.json"}) {
      Identity id;
      if (!identify(path, &id)) continue;
      auto inode = by_inode.find({id.dev, id.ino});
      auto real = by_path.find(id.real);
      const std::string* input = inode != by_inode.end() ? &inode->second
                                 : real != by_path.end() ? &real->second
                                                         : nullptr;
      if (input)
        return makeError("output " + path + " would overwrite the input " + *input +
                         " (same file); choose another output path");
    }
  }
  return Status();
}

}  // namespace smpl
