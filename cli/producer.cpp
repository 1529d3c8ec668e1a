// producerBase/producerHash: see producer.h for what enters the hash.
#include "cli/producer.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "core/io/file_io.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

// Options that do not change the bytes written, and those naming inputs
// (hashed by identity below).
const char* const kNotHashed[] = {
    "--threads",    "--quiet",        "-q",      "--force",    "--out",   "--out-dir",
    "--motion-dir", "--memory-limit", "--shard", "--manifest", "--model", "--motion",
    "--betas-file", "--uv",           "--dmpl",  "--help",     "-h",      "--version"};

bool hashed(const std::string& option) {
  return std::find_if(std::begin(kNotHashed), std::end(kNotHashed),
                      [&](const char* o) { return option == o; }) == std::end(kNotHashed);
}

// A folder (a --model folder): each regular file's name, size and time.
void addFolder(const std::string& dir, ContentHash* h) {
  std::vector<std::string> entries;
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    std::error_code e2;
    if (!it->is_regular_file(e2)) continue;
    const auto size = fs::file_size(it->path(), e2);
    const auto time = fs::last_write_time(it->path(), e2).time_since_epoch().count();
    entries.push_back(it->path().filename().string() + "/" + std::to_string(size) + "/" +
                      std::to_string(time));
  }
  std::sort(entries.begin(), entries.end());
  for (const std::string& e : entries) h->add(e);
}

// An input file by base name and content ("" = not given). Only regular
// files are read: a pipe or device (/dev/stdin, /dev/zero) is named only, so
// hashing never consumes or endlessly reads an input.
Status addInput(const std::string& tag, const std::string& path, ContentHash* h) {
  h->add(tag);
  h->add(baseName(path));
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (path.empty() || ec || (tag == "model" && path == "builtin")) return Status();
  if (fs::is_directory(st)) {
    addFolder(path, h);
    return Status();
  }
  if (!fs::is_regular_file(st)) return Status();
  Result<uint64_t> content = hashFileContent(path);
  if (!content) return content.error();
  h->add(std::to_string(*content));
  return Status();
}

// --dmpl DIR: every basis it can pick (core/load/dmpl.h findDmplBasis), by content.
Status addDmplFolder(const std::string& dir, ContentHash* h) {
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(dir, ec)) return Status();
  for (const char* sub : {"dmpls/", ""})
    for (const char* gender : {"female", "male", "neutral"}) {
      const std::string path = dir + "/" + sub + gender + "/model.npz";
      if (!fs::is_regular_file(path, ec)) continue;
      if (Status st = addInput(std::string("dmpl ") + sub + gender, path, h); !st) return st;
    }
  return Status();
}

}  // namespace

Result<ContentHash> producerBase(const Settings& s) {
  ContentHash h;
  h.add(std::string("smpl-export producer 1"));
  h.add(std::string(SMPL_EXPORT_VERSION));
  std::vector<std::pair<std::string, std::string>> options;
  for (const auto& o : s.given_options)
    if (hashed(o.first)) options.push_back(o);
  std::sort(options.begin(), options.end());
  for (const auto& [name, value] : options) h.add(name + "=" + value);
  if (Status st = addInput("model", s.model, &h); !st) return st.error();
  if (Status st = addInput("betas", s.betas_file, &h); !st) return st.error();
  if (Status st = addInput("uv", s.export_options.uv_obj, &h); !st) return st.error();
  if (Status st = addInput("dmpl", s.dmpl, &h); !st) return st.error();
  if (Status st = addDmplFolder(s.dmpl, &h); !st) return st.error();
  return h;
}

std::string producerHash(ContentHash base, const std::vector<std::string>& motions) {
  for (const std::string& m : motions) {
    std::error_code ec;
    const auto size = fs::file_size(m, ec);
    base.add("motion " + baseName(m) + " " + (ec ? std::string("?") : std::to_string(size)));
  }
  return base.hex();
}

}  // namespace smpl
