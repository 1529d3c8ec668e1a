#include "core/models/uv_split.h"

#include <map>

namespace smpl {

Result<UvLayout> splitUvSeams(const std::vector<UvPolygon>& polygons,
                              const std::vector<Eigen::Vector2f>& uv_list, int n,
                              const std::string& context) {
  UvLayout layout;
  std::map<std::pair<int, int>, int>
      index;  // (v, vt) -> asset vertex; ordered map keeps output deterministic
  std::vector<Eigen::Vector2f> uvs;
  std::vector<Eigen::Vector3i> triangles;
  for (const UvPolygon& face : polygons) {
    std::vector<int> ids;
    for (const auto& [v, vt] : face) {
      if (v < 0 || v >= n || vt < 0 || vt >= static_cast<int>(uv_list.size()))
        return makeError(context + ": face index out of range (vertex " + std::to_string(v + 1) +
                         ", uv " + std::to_string(vt + 1) + ")");
      auto [it, added] =
          index.emplace(std::make_pair(v, vt), static_cast<int>(layout.source_vertex.size()));
      if (added) {
        layout.source_vertex.push_back(v);
        uvs.push_back(uv_list[vt]);
      }
      ids.push_back(it->second);
    }
    for (size_t i = 1; i + 1 < ids.size(); ++i) triangles.emplace_back(ids[0], ids[i], ids[i + 1]);
  }
  layout.uvs.resize(static_cast<Eigen::Index>(uvs.size()), 2);
  for (size_t i = 0; i < uvs.size(); ++i) layout.uvs.row(i) = uvs[i].transpose();
  layout.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t i = 0; i < triangles.size(); ++i) layout.triangles.row(i) = triangles[i].transpose();
  return layout;
}

Result<UvLayout> splitUvSeams(const Eigen::MatrixXi& faces, const Eigen::MatrixXi& uv_faces,
                              const Eigen::MatrixXd& uvs, int n, const std::string& context) {
  if (uv_faces.rows() != faces.rows() || uv_faces.cols() != 3 || uvs.cols() != 2)
    return makeError(context + ": UV faces have shape (" + std::to_string(uv_faces.rows()) + "," +
                     std::to_string(uv_faces.cols()) + "); expected (" +
                     std::to_string(faces.rows()) + ",3), one row per model face");
  std::vector<UvPolygon> polygons(static_cast<size_t>(faces.rows()));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int c = 0; c < 3; ++c) polygons[f].emplace_back(faces(f, c), uv_faces(f, c));
  std::vector<Eigen::Vector2f> list(static_cast<size_t>(uvs.rows()));
  for (Eigen::Index i = 0; i < uvs.rows(); ++i) list[i] = uvs.row(i).transpose().cast<float>();
  return splitUvSeams(polygons, list, n, context);
}

}  // namespace smpl
