#include "core/models/uv_obj.h"

#include <climits>
#include <cstdlib>
#include <sstream>
#include <utility>

#include "core/io/file_io.h"
#include "core/io/printable.h"
#include "core/models/validate_inputs.h"

namespace smpl {
namespace {

struct ObjData {
  int positions = 0;
  std::vector<Eigen::Vector2f> uvs;
  std::vector<std::vector<std::pair<int, int>>> faces;  // (v, vt), 0-based
};

// "12/5/7" or "12/5" -> (v, vt); negative indices count from the end (OBJ spec).
bool parseCorner(const std::string& token, const ObjData& obj, std::pair<int, int>* corner) {
  size_t slash = token.find('/');
  if (slash == std::string::npos) return false;
  char* end = nullptr;
  long v = std::strtol(token.c_str(), &end, 10);
  long vt = std::strtol(token.c_str() + slash + 1, &end, 10);
  // Indices beyond the int range would wrap into a valid-looking vertex.
  if (v == 0 || vt == 0 || std::labs(v) > INT_MAX || std::labs(vt) > INT_MAX) return false;
  corner->first = static_cast<int>(v > 0 ? v - 1 : obj.positions + v);
  corner->second = static_cast<int>(vt > 0 ? vt - 1 : static_cast<long>(obj.uvs.size()) + vt);
  return true;
}

Result<ObjData> parseObj(const std::string& path) {
  // Through readFileBytes: devices are refused, the first bytes must be text and
  // the size within 256 MiB (kUvObjInput) before the rest is read, and the
  // buffer is charged to the memory budget.
  Result<std::vector<uint8_t>> bytes = readFileBytes(path, kUvObjInput);
  if (!bytes) return bytes.error();
  std::istringstream in(std::string(bytes->begin(), bytes->end()));
  bytes = std::vector<uint8_t>();
  ObjData obj;
  std::string line, tag;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    std::istringstream ls(line);
    if (!(ls >> tag)) continue;
    if (tag == "v") {
      ++obj.positions;
    } else if (tag == "vt") {
      double uv[2];  // as doubles, so 1e39 is named as out of range, not as malformed
      if (!(ls >> uv[0] >> uv[1]))
        return makeError(path + ":" + std::to_string(line_no) + ": malformed 'vt' line");
      const std::string where = path + ":" + std::to_string(line_no);
      if (Status st = checkTexCoords(uv, 2, where, "'vt'"); !st) return st.error();
      obj.uvs.push_back(Eigen::Vector2f(static_cast<float>(uv[0]), static_cast<float>(uv[1])));
    } else if (tag == "f") {
      std::vector<std::pair<int, int>> face;
      for (std::string token; ls >> token;) {
        std::pair<int, int> corner;
        if (!parseCorner(token, obj, &corner))
          return makeError(path + ":" + std::to_string(line_no) + ": face corner '" +
                           printable(token, 64) + "' is not v/vt with indices in the int range");
        face.push_back(corner);
      }
      if (face.size() < 3)
        return makeError(path + ":" + std::to_string(line_no) + ": face with fewer than 3 corners");
      obj.faces.push_back(std::move(face));
    }
  }
  return obj;
}

}  // namespace

Result<UvLayout> loadUvLayout(const std::string& path, const BodyModel& model) {
  Result<ObjData> obj = parseObj(path);
  if (!obj) return obj.error();
  const int n = model.numVertices();
  if (obj->positions != 0 && obj->positions != n)
    return makeError(path + ": has " + std::to_string(obj->positions) +
                     " vertices; the model has " + std::to_string(n) +
                     " (the UV mesh must share the model's vertex order)");
  if (obj->faces.empty()) return makeError(path + ": no faces with texture coordinates");
  return splitUvSeams(obj->faces, obj->uvs, n, path);
}

}  // namespace smpl
