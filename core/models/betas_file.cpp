#include "core/models/betas_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/io/npz.h"
#include "core/models/betas_rows.h"
#include "core/models/validate_inputs.h"

namespace smpl {
namespace {

// (B,), (1,B) or per-frame (T,B) from a numpy file. What a betas file is
// (kBetasInput: .npy/.npz up to 256 MiB, JSON 64 MiB, core/io/input_kind.h) is
// checked from its first bytes and size before it is read.
Result<std::vector<double>> readNumpyBetas(const std::string& path, std::string* note) {
  Array a;
  if (hasSuffix(path, ".npy")) {
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
  Result<BetasRows> rows = collapseBetasRows(a, path);
  if (!rows) return rows.error();
  if (rows->averaged && note) *note = betasRowsNote(*rows);
  return rows->betas;
}

Result<std::vector<double>> readJsonBetas(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = readFileBytes(path, kBetasInput);  // sniffed, bounded
  if (!bytes) return bytes.error();
  nlohmann::json j = nlohmann::json::parse(bytes->begin(), bytes->end(), nullptr,
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

}  // namespace

Result<std::vector<double>> readBetasFile(const std::string& path, std::string* note) {
  Result<std::vector<double>> betas = hasSuffix(path, ".npy") || hasSuffix(path, ".npz")
                                          ? readNumpyBetas(path, note)
                                          : readJsonBetas(path);
  if (!betas) return betas;
  if (Status st = checkCoefficients(*betas, path, "'betas'"); !st) return st.error();
  return betas;
}

}  // namespace smpl
