#include "core/models/uv_npy.h"

#include <cmath>
#include <filesystem>

#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/models/validate_inputs.h"
#include "core/os/path.h"

namespace smpl {
namespace {

// Without opening it: a FIFO must not block here (readNpyFile refuses special files).
bool exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(os::fsPath(path), ec);
}

Result<Eigen::MatrixXd> readMatrix(const std::string& path, int64_t rows, int64_t cols,
                                   const char* what) {
  Result<Array> a = readNpyFile(path, kUvNpyInput);  // .npy magic, 256 MiB, before reading
  if (!a) return a.error();
  const bool ok = !a->isString() && !a->isObject() && a->shape.size() == 2 && a->shape[1] == cols &&
                  (rows < 0 || a->shape[0] == rows);
  if (!ok)
    return makeError(baseName(path) + ": " + what + " has shape " + shapeString(a->shape) +
                     "; expected (" + (rows < 0 ? std::string("U") : std::to_string(rows)) + "," +
                     std::to_string(cols) + ")");
  for (double v : a->data)
    if (!std::isfinite(v))
      return makeError(baseName(path) + ": " + what + " contains NaN or infinite values");
  if (cols == 2)  // coordinates (faces are checked as indices by the caller)
    if (Status st = checkTexCoords(a->data.data(), a->data.size(), baseName(path), what); !st)
      return st.error();
  return Eigen::MatrixXd(
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          a->data.data(), a->shape[0], cols));
}

}  // namespace

Result<std::pair<std::string, std::string>> uvNumpyPairPaths(const std::string& path) {
  std::string stem;
  for (const char* suffix : {"_uv.npy", "_vt.npy", "_ft.npy"})
    if (hasSuffix(path, suffix)) stem = path.substr(0, path.size() - 7);
  if (stem.empty())
    return makeError(
        path + ": numpy UVs must be a pair named <stem>_uv.npy (or _vt.npy) and <stem>_ft.npy");
  if (!exists(path)) return makeError(path + ": cannot open: No such file or directory");
  std::string coords = stem + "_uv.npy";
  if (!exists(coords) && exists(stem + "_vt.npy")) coords = stem + "_vt.npy";
  const std::string faces = stem + "_ft.npy";
  for (const std::string& p : {coords, faces})
    if (!exists(p))
      return makeError(path + ": its partner " + baseName(p) +
                       " does not exist (UV pairs are <stem>_uv.npy + <stem>_ft.npy)");
  return std::make_pair(coords, faces);
}

Result<UvLayout> loadUvNumpyPair(const std::string& path, const BodyModel& model) {
  Result<std::pair<std::string, std::string>> paths = uvNumpyPairPaths(path);
  if (!paths) return paths.error();
  Result<Eigen::MatrixXd> uvs = readMatrix(paths->first, -1, 2, "UV coordinates");
  if (!uvs) return uvs.error();
  Result<Eigen::MatrixXd> ft =
      readMatrix(paths->second, model.faces.rows(), 3, "UV faces (one row per model face)");
  if (!ft) return ft.error();
  const double u = static_cast<double>(uvs->rows());
  for (Eigen::Index i = 0; i < ft->size(); ++i) {
    const double v = ft->data()[i];
    if (v < 0 || v >= u || v != std::floor(v))
      return makeError(
          baseName(paths->second) + ": index " + std::to_string(static_cast<long long>(v)) +
          " out of range; expected integers in [0," + std::to_string(uvs->rows()) + ") ('" +
          baseName(paths->first) + "' has " + std::to_string(uvs->rows()) + " rows)");
  }
  return splitUvSeams(model.faces, ft->cast<int>(), *uvs, model.numVertices(),
                      baseName(paths->second));
}

}  // namespace smpl
