#include "cli/betas_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/io/npz.h"
#include "core/load/betas_rows.h"

namespace smpl {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

Result<std::vector<double>> readBetasFile(const std::string& path, std::string* note) {
  // What a betas file is (kBetasInput: .npy/.npz up to 256 MiB, JSON 64 MiB)
  // is checked from its first bytes and size before it is read.
  if (endsWith(path, ".npy") || endsWith(path, ".npz")) {
    Array a;
    if (endsWith(path, ".npy")) {
      Result<Array> r = readNpyFile(path, kBetasInput);
      if (!r) return r.error();
      a = std::move(*r);
    } else {
      if (Result<FileFormat> f = checkInputFile(path, kBetasInput); !f) return f.error();
      Result<ArrayDict> d = readNpzFile(path, {"betas"});  // lazy: other members are not read
      if (!d) return d.error();
      auto it = d->find("betas");
      if (it == d->end()) return makeError(path + ": missing key 'betas'");
      a = it->second;
    }
    Result<BetasRows> rows = collapseBetasRows(a, path);  // (B,), (1,B) or per frame (T,B)
    if (!rows) return rows.error();
    if (rows->averaged && note) *note = betasRowsNote(*rows);
    return rows->betas;
  }
  Result<std::vector<uint8_t>> text = readFileBytes(path, kBetasInput);
  if (!text) return text.error();
  nlohmann::json j = nlohmann::json::parse(text->begin(), text->end(), nullptr,
                                           /*allow_exceptions=*/false);
  if (j.is_discarded()) return makeError(path + ": not valid JSON");
  if (j.is_object() && j.contains("betas")) j = j["betas"];
  if (!j.is_array())
    return makeError(path + ": expected a JSON array of numbers or {\"betas\": [...]}");
  std::vector<double> betas;
  for (const auto& v : j) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      return makeError(path + ": 'betas' holds a non-number");
    betas.push_back(v.get<double>());
  }
  return betas;
}

}  // namespace smpl
