// producerBase/producerHash: see producer.h for what enters the hash.
#include "request/producer.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "core/io/file_io.h"
#include "core/models/model_folder.h"
#include "core/os/path.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

// A folder (a --model folder): each file a model could be picked from
// (core/models/model_folder.h, two levels deep), by relative path, size and time.
void addFolder(const std::string& dir, ContentHash* h) {
  for (const std::string& rel : listModelFolder(dir)) {
    std::error_code ec;
    const fs::path path = os::fsPath(dir) / os::fsPath(rel);
    const auto size = static_cast<unsigned long long>(fs::file_size(path, ec));
    // long long: the count may be wider (emscripten's libc++: __int128)
    const auto time =
        static_cast<long long>(fs::last_write_time(path, ec).time_since_epoch().count());
    h->add(rel + "/" + std::to_string(size) + "/" + std::to_string(time));
  }
}

// An input file by base name and content ("" = not given). Only regular
// files are read: a pipe or device (/dev/stdin, /dev/zero) is named only, so
// hashing never consumes or endlessly reads an input.
Status addInput(const std::string& tag, const std::string& path, ContentHash* h) {
  h->add(tag);
  h->add(baseName(path));
  std::error_code ec;
  const fs::file_status st = fs::status(os::fsPath(path), ec);
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

// --dmpl DIR: every basis it can pick (core/models/dmpl.h findDmplBasis), by content.
Status addDmplFolder(const std::string& dir, ContentHash* h) {
  std::error_code ec;
  if (dir.empty() || !fs::is_directory(os::fsPath(dir), ec)) return Status();
  for (const char* sub : {"dmpls/", ""})
    for (const char* gender : {"female", "male", "neutral"}) {
      const std::string path = dir + "/" + sub + gender + "/model.npz";
      if (!fs::is_regular_file(os::fsPath(path), ec)) continue;
      if (Status st = addInput(std::string("dmpl ") + sub + gender, path, h); !st) return st;
    }
  return Status();
}

}  // namespace

Result<ContentHash> producerBase(const ExportRequest& s) {
  ContentHash h;
  h.add(std::string("smpl-export producer 1"));
  h.add(std::string(SMPL_EXPORT_VERSION));
  std::vector<std::pair<std::string, std::string>> options = s.hashed_options;
  std::sort(options.begin(), options.end());
  for (const auto& [name, value] : options) h.add(name + "=" + value);
  if (Status st = addInput("model", s.model, &h); !st) return st.error();
  if (Status st = addInput("betas", s.betas_file, &h); !st) return st.error();
  if (Status st = addInput("uv", s.asset.uv_obj, &h); !st) return st.error();
  if (Status st = addInput("dmpl", s.dmpl, &h); !st) return st.error();
  if (Status st = addDmplFolder(s.dmpl, &h); !st) return st.error();
  return h;
}

namespace {

// One motion input by identity: "<tag> <name> <size>", or for a folder
// (--motion-sequence DIR, --hands DIR) its name and each file's name and size.
void addMotionInput(const char* tag, const char* folder_tag, const std::string& m,
                    ContentHash* base) {
  std::error_code ec;
  if (fs::is_directory(os::fsPath(m), ec)) {
    std::vector<std::string> files;
    for (auto it = fs::directory_iterator(os::fsPath(m), ec); !ec && it != fs::directory_iterator();
         it.increment(ec)) {
      std::error_code e2;
      const auto size = it->is_regular_file(e2) ? it->file_size(e2) : 0;
      files.push_back(os::utf8(it->path().filename()) + " " + std::to_string(size));
    }
    std::sort(files.begin(), files.end());
    base->add(std::string(folder_tag) + " " + baseName(m));
    for (const std::string& f : files) base->add(f);
    return;
  }
  const auto size = fs::file_size(os::fsPath(m), ec);
  base->add(std::string(tag) + " " + baseName(m) + " " +
            (ec ? std::string("?") : std::to_string(size)));
}

}  // namespace

std::string producerHash(ContentHash base, const std::vector<std::string>& motions,
                         const std::vector<std::string>& hands) {
  for (const std::string& m : motions) addMotionInput("motion", "sequence", m, &base);
  for (const std::string& h : hands) addMotionInput("hands", "hands folder", h, &base);
  return base.hex();
}

}  // namespace smpl
