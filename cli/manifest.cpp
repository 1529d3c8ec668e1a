#include "cli/manifest.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/io/file_io.h"

namespace smpl {

std::string manifestLine(const ManifestEntry& e) {
  nlohmann::ordered_json j;
  j["input"] = e.input;
  j["output"] = e.output.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(e.output);
  j["bytes"] = e.sha256.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(e.bytes);
  j["sha256"] = e.sha256.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(e.sha256);
  j["seconds"] = std::round(e.seconds * 1e4) / 1e4;
  j["status"] = e.status;
  if (e.status == "failed") j["error"] = e.message;
  if (e.status == "skipped") j["reason"] = e.message;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

Status writeManifest(const std::string& path, std::vector<ManifestEntry> entries) {
  std::sort(entries.begin(), entries.end(),
            [](const ManifestEntry& a, const ManifestEntry& b) { return a.input < b.input; });
  std::string text;
  for (const ManifestEntry& e : entries) text += manifestLine(e) + "\n";
  return writeFileAtomic(path, text);
}

}  // namespace smpl
