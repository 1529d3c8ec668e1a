// Polygonising the demo body's implicit surface with marching cubes.
//
// Instead of the classic 256-case table, each cube's polygons are traced from
// its faces: every cube face contributes directed segments between the edges
// where the field changes sign, oriented so the inside lies on one fixed
// side, and ambiguous faces (four crossings) are resolved by the asymptotic
// decider, which depends on that face's four values only. Neighbouring cubes
// therefore agree on every shared segment (in opposite directions), so the
// surface is closed, manifold and consistently oriented by construction.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "core/demo/demo_body_internal.h"

namespace smpl {
namespace demo {
namespace {

struct Grid {
  V3 origin;
  double h = 0;
  int nx = 0, ny = 0, nz = 0;
  std::vector<double> f;  // field at grid points, never exactly 0
  int index(int i, int j, int k) const { return i + nx * (j + ny * k); }
  V3 point(int i, int j, int k) const { return origin + V3{i * h, j * h, k * h}; }
};

Grid sampleField(const Rig& rig, double cell) {
  V3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
  for (const Part& p : rig.parts)
    for (const V3& c : {p.a, p.b}) {
      const double r =
          std::max(p.ra, p.rb) * std::max(p.squash.x, std::max(p.squash.y, p.squash.z));
      lo = {std::min(lo.x, c.x - r), std::min(lo.y, c.y - r), std::min(lo.z, c.z - r)};
      hi = {std::max(hi.x, c.x + r), std::max(hi.y, c.y + r), std::max(hi.z, c.z + r)};
    }
  Grid g;
  g.h = cell;
  // x = 0 is a grid plane, so the sampling is mirror-symmetric like the body.
  const int half_x = static_cast<int>(std::ceil(std::max(-lo.x, hi.x) / cell)) + 2;
  g.origin = {-half_x * cell, lo.y - 2 * cell, lo.z - 2 * cell};
  g.nx = 2 * half_x + 1;
  g.ny = static_cast<int>(std::ceil((hi.y - lo.y) / cell)) + 5;
  g.nz = static_cast<int>(std::ceil((hi.z - lo.z) / cell)) + 5;
  g.f.resize(static_cast<size_t>(g.nx) * g.ny * g.nz);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        double v = bodyField(rig, g.point(i, j, k));
        if (std::abs(v) < 1e-12) v = 1e-12;  // no surface vertex exactly on a grid point
        g.f[g.index(i, j, k)] = v;
      }
  return g;
}

// Cube faces, corners counter-clockwise around the outward normal; corner c
// sits at offset (c & 1, c >> 1 & 1, c >> 2 & 1).
const int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                          {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

// Local edge id between two corners differing in one bit: lower corner * 3 + axis.
int localEdge(int c0, int c1) {
  const int diff = c0 ^ c1;
  const int axis = diff == 1 ? 0 : diff == 2 ? 1 : 2;
  return std::min(c0, c1) * 3 + axis;
}

class Extractor {
 public:
  explicit Extractor(const Grid& g) : g_(g) {
    for (auto& a : edge_vertex_) a.assign(g.f.size(), -1);
  }

  void run() {
    for (int k = 0; k + 1 < g_.nz; ++k)
      for (int j = 0; j + 1 < g_.ny; ++j)
        for (int i = 0; i + 1 < g_.nx; ++i) cube(i, j, k);
  }

  std::vector<V3> vertices;
  std::vector<std::array<int, 3>> faces;

 private:
  double value(int c) const {
    return g_.f[g_.index(ci_ + (c & 1), cj_ + (c >> 1 & 1), ck_ + (c >> 2 & 1))];
  }

  int vertex(int local) {
    const int c = local / 3, axis = local % 3;
    const int i = ci_ + (c & 1), j = cj_ + (c >> 1 & 1), k = ck_ + (c >> 2 & 1);
    int& id = edge_vertex_[axis][g_.index(i, j, k)];
    if (id >= 0) return id;
    const int i1 = i + (axis == 0), j1 = j + (axis == 1), k1 = k + (axis == 2);
    const double f0 = g_.f[g_.index(i, j, k)], f1 = g_.f[g_.index(i1, j1, k1)];
    const double t = f0 / (f0 - f1);
    id = static_cast<int>(vertices.size());
    vertices.push_back(g_.point(i, j, k) * (1 - t) + g_.point(i1, j1, k1) * t);
    return id;
  }

  // Directed segments of one face: from each outside->inside crossing to an
  // inside->outside crossing, so the inside is always on the same side.
  bool faceSegments(const int* corners, int* next) const {
    double v[4];
    bool in[4];
    for (int q = 0; q < 4; ++q) in[q] = (v[q] = value(corners[q])) < 0;
    int crossings = 0;
    for (int q = 0; q < 4; ++q) crossings += in[q] != in[(q + 1) % 4];
    if (crossings == 0) return false;
    // Asymptotic decider: if the bilinear saddle is inside, the inside corners
    // connect across the face and the outside corners are cut off.
    const bool inside_connected =
        crossings == 4 && (v[0] * v[2] - v[1] * v[3]) / (v[0] + v[2] - v[1] - v[3]) < 0;
    for (int q = 0; q < 4; ++q) {
      if (in[q] || !in[(q + 1) % 4]) continue;  // not an outside->inside crossing
      int end = (q + 1) % 4;                    // next crossing forward
      if (crossings == 2)
        while (in[end] == in[(end + 1) % 4]) end = (end + 1) % 4;
      else if (inside_connected)
        end = (q + 3) % 4;
      next[localEdge(corners[q], corners[(q + 1) % 4])] =
          localEdge(corners[end], corners[(end + 1) % 4]);
    }
    return crossings == 4;
  }

  void cube(int i, int j, int k) {
    ci_ = i, cj_ = j, ck_ = k;
    int next[24];
    std::fill(next, next + 24, -1);
    bool ambiguous = false;
    for (const auto& face : kFaces) ambiguous |= faceSegments(face, next);
    bool visited[24] = {};
    for (int start = 0; start < 24; ++start) {
      if (next[start] < 0 || visited[start]) continue;
      std::vector<int> loop;
      for (int e = start; !visited[e]; e = next[e]) {
        visited[e] = true;
        loop.push_back(vertex(e));
      }
      triangulate(loop, ambiguous);
    }
  }

  // A fan from the first vertex, except next to an ambiguous face, where a
  // fan diagonal could duplicate one made by the neighbouring cube: there a
  // centre vertex keeps every edge shared by exactly two triangles.
  void triangulate(const std::vector<int>& loop, bool ambiguous) {
    const int n = static_cast<int>(loop.size());
    if (n == 3 || !ambiguous) {
      for (int q = 1; q + 1 < n; ++q) faces.push_back({loop[0], loop[q], loop[q + 1]});
      return;
    }
    V3 c;
    for (int v : loop) c = c + vertices[v];
    const int centre = static_cast<int>(vertices.size());
    vertices.push_back(c * (1.0 / n));
    for (int q = 0; q < n; ++q) faces.push_back({centre, loop[q], loop[(q + 1) % n]});
  }

  const Grid& g_;
  std::array<std::vector<int>, 3> edge_vertex_;
  int ci_ = 0, cj_ = 0, ck_ = 0;
};

int findRoot(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Keeps the connected component with the most faces (drops specks that a
// coarse grid can cut off thin parts) and renumbers vertices in order.
Mesh largestComponent(const std::vector<V3>& vertices,
                      const std::vector<std::array<int, 3>>& faces) {
  std::vector<int> parent(vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& f : faces)
    for (int q = 1; q < 3; ++q) parent[findRoot(parent, f[q])] = findRoot(parent, f[0]);
  std::vector<int> count(vertices.size(), 0);
  for (const auto& f : faces) ++count[findRoot(parent, f[0])];
  const int best = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
  std::vector<int> remap(vertices.size(), -1);
  std::vector<V3> kept;
  std::vector<std::array<int, 3>> kept_faces;
  for (const auto& f : faces) {
    if (findRoot(parent, f[0]) != best) continue;
    std::array<int, 3> nf;
    for (int q = 0; q < 3; ++q) {
      if (remap[f[q]] < 0) {
        remap[f[q]] = static_cast<int>(kept.size());
        kept.push_back(vertices[f[q]]);
      }
      nf[q] = remap[f[q]];
    }
    kept_faces.push_back(nf);
  }
  Mesh m;
  m.vertices.resize(kept.size(), 3);
  for (size_t v = 0; v < kept.size(); ++v) m.vertices.row(v) << kept[v].x, kept[v].y, kept[v].z;
  m.faces.resize(kept_faces.size(), 3);
  for (size_t f = 0; f < kept_faces.size(); ++f)
    m.faces.row(f) << kept_faces[f][0], kept_faces[f][1], kept_faces[f][2];
  return m;
}

V3 gradient(const Rig& rig, V3 p) {
  const double e = 1e-4;
  return V3{bodyField(rig, p + V3{e, 0, 0}) - bodyField(rig, p - V3{e, 0, 0}),
            bodyField(rig, p + V3{0, e, 0}) - bodyField(rig, p - V3{0, e, 0}),
            bodyField(rig, p + V3{0, 0, e}) - bodyField(rig, p - V3{0, 0, e})} *
         (0.5 / e);
}

// Newton steps onto the zero level set along the gradient.
V3 project(const Rig& rig, V3 p) {
  for (int it = 0; it < 2; ++it) {
    const V3 g = gradient(rig, p);
    const double g2 = dot(g, g);
    if (g2 < 1e-12) break;
    p = p - g * (bodyField(rig, p) / g2);
  }
  return p;
}

// Tangential Laplacian smoothing evens out the slivers marching cubes makes
// near grid points; each step is projected back onto the surface.
void relax(const Rig& rig, Mesh* m, int iterations) {
  const int n = static_cast<int>(m->vertices.rows());
  std::vector<std::vector<int>> nbr(n);
  for (int f = 0; f < m->faces.rows(); ++f)
    for (int q = 0; q < 3; ++q) nbr[m->faces(f, q)].push_back(m->faces(f, (q + 1) % 3));
  std::vector<V3> p(n), next(n);
  for (int v = 0; v < n; ++v)
    p[v] = project(rig, {m->vertices(v, 0), m->vertices(v, 1), m->vertices(v, 2)});
  for (int it = 0; it < iterations; ++it) {
    for (int v = 0; v < n; ++v) {
      V3 avg;
      for (int u : nbr[v]) avg = avg + p[u];
      V3 d = avg * (1.0 / nbr[v].size()) - p[v];
      const V3 g = gradient(rig, p[v]);
      const double g2 = dot(g, g);
      if (g2 < 1e-12) {
        next[v] = p[v];
        continue;
      }
      // Move along the tangent plane, then one Newton step back onto the
      // surface reusing this gradient (the move is a fraction of a cell).
      const V3 q = p[v] + (d - g * (dot(d, g) / g2)) * 0.5;
      next[v] = q - g * (bodyField(rig, q) / g2);
    }
    p.swap(next);
  }
  for (int v = 0; v < n; ++v) p[v] = project(rig, p[v]);
  for (int v = 0; v < n; ++v) m->vertices.row(v) << p[v].x, p[v].y, p[v].z;
}

}  // namespace

Mesh polygonise(const Rig& rig, double cell) {
  const Grid grid = sampleField(rig, cell);
  Extractor ex(grid);
  ex.run();
  Mesh m = largestComponent(ex.vertices, ex.faces);
  relax(rig, &m, 3);
  return m;
}

}  // namespace demo
}  // namespace smpl
