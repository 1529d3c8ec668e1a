#include "core/models/dmpl.h"

#include <filesystem>

#include "core/io/file_io.h"
#include "core/models/model_folder.h"
#include "core/models/npz_arrays.h"
#include "core/models/validate_inputs.h"
#include "core/os/path.h"

namespace smpl {

Result<DmplBasis> loadDmplBasis(const std::string& path, int num_vertices, int count) {
  // An .npz in a regular file, within its bound, before anything is mapped.
  if (Result<FileFormat> f = checkInputFile(path, kDmplInput); !f) return f.error();
  Result<ArrayDict> arrays = readNpzArrays(path, {"eigvec"}, path);
  if (!arrays) return arrays.error();
  auto it = arrays->find("eigvec");
  if (it == arrays->end())
    return makeError(path + ": no 'eigvec' (expected a DMPL basis of shape (N,3,D))");
  const Array& a = it->second;
  if (a.isString() || a.shape.size() != 3 || a.shape[0] != num_vertices || a.shape[1] != 3 ||
      a.shape[2] < 1)
    return makeError(path + ": 'eigvec' has shape " + shapeString(a.shape) +
                     "; expected (N,3,D) with N=" + std::to_string(num_vertices) +
                     " (the model's vertex count)");
  const int d = static_cast<int>(a.shape[2]);
  if (count < 0 || count > d)
    return makeError(path + ": --dmpl-count " + std::to_string(count) + ": the basis has " +
                     std::to_string(d) + " directions");
  if (Status st = checkDmplBasisValues(a, path); !st) return st.error();
  const int keep = count == 0 ? d : count;
  DmplBasis basis;
  basis.path = path;
  const uint64_t bytes = 3ull * static_cast<uint64_t>(num_vertices) * keep * sizeof(double);
  if (Status st = basis.charge.add(bytes, path, "the DMPL basis"); !st) return st.error();
  basis.directions.resize(3 * static_cast<Eigen::Index>(num_vertices), keep);
  for (Eigen::Index r = 0; r < basis.directions.rows(); ++r)
    for (int k = 0; k < keep; ++k) basis.directions(r, k) = a.data[static_cast<size_t>(r) * d + k];
  return basis;
}

Result<std::string> findDmplBasis(const std::string& dir, const std::string& gender,
                                  std::string* note) {
  namespace fs = std::filesystem;
  const std::string wanted = normalizeGender(gender).empty() ? "neutral" : normalizeGender(gender);
  std::string tried;
  for (const std::string& g : {wanted, std::string("neutral")}) {
    for (const std::string& sub : {std::string("dmpls/"), std::string()}) {
      const std::string p = dir + "/" + sub + g + "/model.npz";
      std::error_code ec;
      if (fs::is_regular_file(os::fsPath(p), ec)) {
        if (g != wanted && note) *note = "no " + wanted + " DMPL basis in " + dir + "; using " + p;
        return p;
      }
      if (tried.find(sub + g + "/") == std::string::npos)
        tried += (tried.empty() ? "" : ", ") + sub + g + "/model.npz";
    }
  }
  return makeError(dir + ": no DMPL basis for gender '" + wanted + "' (looked for " + tried + ")");
}

}  // namespace smpl
