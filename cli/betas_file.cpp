#include "cli/betas_file.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

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
  if (endsWith(path, ".npy") || endsWith(path, ".npz")) {
    Array a;
    if (endsWith(path, ".npy")) {
      Result<Array> r = readNpyFile(path);
      if (!r) return r.error();
      a = std::move(*r);
    } else {
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
  std::ifstream in(path);
  if (!in) return makeError(path + ": cannot open");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
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
