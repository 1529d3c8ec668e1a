// mjcfParts: see mjcf_parts.h.
#include "writers/mjcf/mjcf_parts.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

namespace smpl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFloorRadius = 0.01;    // m: the sphere of a part with no triangles
constexpr double kFlatRegular = 0.005;   // m: added to the second moments' diagonal
constexpr double kMinRadius = 0.001;     // m: thinnest capsule
constexpr double kMinSegment = 0.0001;   // m: shorter capsules become spheres
constexpr double kMinThickness = 0.001;  // m: thinner point sets get no hull
const double kFloorVolume = 4.0 / 3.0 * kPi * kFloorRadius * kFloorRadius * kFloorRadius;

Eigen::Vector3d vertex(const SkinnedMesh& m, int v) { return m.positions.row(v).cast<double>(); }

// The joint with the largest weight in `row` (K wide), ties the lower index.
int argmax(const Eigen::VectorXd& row) {
  int best = 0;
  for (int k = 1; k < row.size(); ++k)
    if (row[k] > row[best]) best = k;
  return best;
}

// Vertex v's weights as a K-vector.
Eigen::VectorXd weightRow(const SkinnedMesh& m, int v, int k_count) {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(k_count);
  for (int c = 0; c < m.joints.cols(); ++c) row[m.joints(v, c)] += m.weights(v, c);
  return row;
}

std::vector<int> triangleParts(const SkinnedMesh& m, int k_count) {
  std::vector<int> part(size_t(m.triangles.rows()));
  for (int t = 0; t < m.triangles.rows(); ++t) {
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(k_count);
    for (int c = 0; c < 3; ++c) sum += weightRow(m, m.triangles(t, c), k_count);
    part[size_t(t)] = argmax(sum);
  }
  return part;
}

double tetra(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& apex) {
  return (a - apex).dot((b - apex).cross(c - apex)) / 6.0;
}

// Centroid, share weight and inertia per kg of part k from its triangles.
MjcfPart partOf(const SkinnedMesh& m, const std::vector<int>& tris, const Eigen::Vector3d& joint) {
  MjcfPart p;
  if (tris.empty()) {
    p.center = joint;
    p.volume = kFloorVolume;
    p.inertia_per_kg = Eigen::Matrix3d::Identity() * (0.4 * kFloorRadius * kFloorRadius);
    return p;
  }
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int t : tris)
    for (int i = 0; i < 3; ++i) c += vertex(m, m.triangles(t, i));
  c /= double(3 * tris.size());
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  double w = 0.0;
  for (int t : tris) {
    const Eigen::Vector3d a = vertex(m, m.triangles(t, 0)), b = vertex(m, m.triangles(t, 1)),
                          d = vertex(m, m.triangles(t, 2));
    w += tetra(a, b, d, c);
    for (const Eigen::Vector3d& v : {a, b, d}) s += (v - c) * (v - c).transpose();
  }
  s /= double(3 * tris.size());
  const Eigen::Matrix3d solid =
      0.6 * s + Eigen::Matrix3d::Identity() * (kFlatRegular * kFlatRegular);
  p.center = c;
  p.volume = std::max(w, kFloorVolume);
  p.inertia_per_kg = Eigen::Matrix3d::Identity() * solid.trace() - solid;
  return p;
}

// The capsule (or sphere) of the vertices in `points`.
MjcfGeom capsuleOf(const std::vector<Eigen::Vector3d>& points) {
  MjcfGeom g;
  if (points.size() < 3) return g;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : points) c += v;
  c /= double(points.size());
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& v : points) s += (v - c) * (v - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(s);
  const double thickness = std::sqrt(std::max(0.0, eig.eigenvalues()[0] / double(points.size())));
  if (points.size() >= 4 && thickness >= kMinThickness) g.hull = points;
  Eigen::Vector3d a = eig.eigenvectors().col(2);  // eigenvalues ascending: the largest
  Eigen::Index big = 0;
  a.cwiseAbs().maxCoeff(&big);
  if (a[big] < 0) a = -a;  // one sign for the same points
  std::vector<double> dist;
  double lo = 0.0, hi = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double t = (points[i] - c).dot(a);
    lo = i == 0 ? t : std::min(lo, t);
    hi = i == 0 ? t : std::max(hi, t);
    dist.push_back((points[i] - c - t * a).norm());
  }
  std::nth_element(dist.begin(), dist.begin() + long(dist.size() / 2), dist.end());
  g.radius = std::max(dist[dist.size() / 2], kMinRadius);
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo) - g.radius;
  if (half * 2 < kMinSegment) {
    g.kind = MjcfGeom::Kind::Sphere;
    g.from = g.to = c + mid * a;
  } else {
    g.kind = MjcfGeom::Kind::Capsule;
    g.from = c + (mid - half) * a;
    g.to = c + (mid + half) * a;
  }
  return g;
}

// Per joint, its dominated vertices (one per model vertex).
std::vector<std::vector<Eigen::Vector3d>> dominatedVertices(const SkinnedMesh& m, int k_count) {
  std::vector<std::vector<Eigen::Vector3d>> out(static_cast<size_t>(k_count));
  std::vector<bool> seen;
  for (int v = 0; v < m.positions.rows(); ++v) {
    const int source = v < int(m.source_vertex.size()) ? m.source_vertex[size_t(v)] : v;
    if (source >= 0) {
      if (size_t(source) >= seen.size()) seen.resize(size_t(source) + 1, false);
      if (seen[size_t(source)]) continue;
      seen[size_t(source)] = true;
    }
    out[size_t(argmax(weightRow(m, v, k_count)))].push_back(vertex(m, v));
  }
  return out;
}

}  // namespace

Result<MjcfParts> mjcfParts(const Asset& asset) {
  const SkinnedMesh& m = asset.mesh;
  const int k_count = int(asset.skeleton.names.size());
  if (m.triangles.rows() == 0 || m.joints.cols() == 0)
    return makeError("MJCF writer: the asset has no skinned mesh (masses come from the mesh)");
  MjcfParts out;
  for (int t = 0; t < m.triangles.rows(); ++t)
    out.mesh_volume += tetra(vertex(m, m.triangles(t, 0)), vertex(m, m.triangles(t, 1)),
                             vertex(m, m.triangles(t, 2)), Eigen::Vector3d::Zero());
  if (!(out.mesh_volume > 0) || !std::isfinite(out.mesh_volume))
    return makeError("MJCF writer: the rest mesh encloses no volume (signed volume " +
                     std::to_string(out.mesh_volume) +
                     " m^3); masses need a closed, outward-oriented mesh");
  const std::vector<int> part = triangleParts(m, k_count);
  std::vector<std::vector<int>> tris(static_cast<size_t>(k_count));
  for (size_t t = 0; t < part.size(); ++t) tris[size_t(part[t])].push_back(int(t));
  const std::vector<std::vector<Eigen::Vector3d>> dominated = dominatedVertices(m, k_count);
  double share_sum = 0.0;
  for (int k = 0; k < k_count; ++k) {
    out.parts.push_back(partOf(m, tris[size_t(k)], asset.skeleton.rest_world.row(k).transpose()));
    out.parts.back().geom = capsuleOf(dominated[size_t(k)]);
    share_sum += out.parts.back().volume;
  }
  for (MjcfPart& p : out.parts) p.volume = out.mesh_volume * p.volume / share_sum;
  return out;
}

}  // namespace smpl
