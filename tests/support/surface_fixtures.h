#pragma once
// Procedural surfaces and independent geometry helpers for the curved-surface stage tests
// (base_mesh, conformal_patch, guidance_field, surface_cells). Written separately from the
// library so the tests do not check the code against itself.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt::test {

//! Shared meshes folder, or empty when ../shared is absent.
inline std::filesystem::path shared_meshes() {
  const std::filesystem::path dir = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data" / "meshes";
  return std::filesystem::is_directory(dir) ? dir : std::filesystem::path();
}

//! Planar grid in z = 0, nx x ny quads of side `h` split along alternating diagonals, counter-
//! clockwise seen from +z. `jitter` (fraction of h) moves interior vertices within the plane.
inline TriMesh flat_grid(int nx, int ny, double h, double jitter = 0.0, uint32_t seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * h, jitter * h);
  TriMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool interior = i > 0 && j > 0 && i < nx && j < ny;
      const double dx = interior ? u(rng) : 0.0, dy = interior ? u(rng) : 0.0;
      m.positions.push_back(Vec3(i * h + dx, j * h + dy, 0.0));
    }
  const auto at = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  return m;
}

//! Rotation taking z to `axis` direction family: a fixed, non-trivial rigid motion for fixtures.
inline Vec3 rigid_motion(const Vec3& p) {
  // Rotation about (1,2,3)/|.| by 0.7 rad (Rodrigues), then a translation.
  const Vec3 k = glm::normalize(Vec3(1.0, 2.0, 3.0));
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Vec3 r = p * c + glm::cross(k, p) * s + k * glm::dot(k, p) * (1.0 - c);
  return r + Vec3(0.3, -1.2, 2.5);
}

//! Open cylinder strip of radius `r` around z: `n_around` segments over `span` radians and
//! `n_up` rows over height `height`; normals point away from the axis.
inline TriMesh cylinder_strip(double r, double span, double height, int n_around, int n_up) {
  TriMesh m;
  for (int j = 0; j <= n_up; ++j)
    for (int i = 0; i <= n_around; ++i) {
      const double a = span * i / n_around;
      m.positions.push_back(Vec3(r * std::cos(a), r * std::sin(a), height * j / n_up));
    }
  const auto at = [n_around](int i, int j) { return j * (n_around + 1) + i; };
  for (int j = 0; j < n_up; ++j)
    for (int i = 0; i < n_around; ++i) {
      // Counter-clockwise seen from outside: angle increases to the right, z upward.
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

//! Closed UV sphere: north pole (vertex 0), `rings` latitude rings of `segments` vertices, south
//! pole last; outward orientation. Ring k (1-based) is at polar angle k * pi / (rings + 1).
inline TriMesh uv_sphere(int rings, int segments, double radius = 1.0, Vec3 centre = Vec3(0.0)) {
  TriMesh m;
  m.positions.push_back(centre + Vec3(0.0, 0.0, radius));
  for (int k = 1; k <= rings; ++k) {
    const double theta = M_PI * k / (rings + 1);
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * M_PI * s / segments;
      m.positions.push_back(centre + radius * Vec3(std::sin(theta) * std::cos(phi),
                                                   std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  }
  m.positions.push_back(centre + Vec3(0.0, 0.0, -radius));
  const int south = static_cast<int>(m.positions.size()) - 1;
  const auto at = [segments](int k, int s) { return 1 + (k - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s), at(1, s + 1)});
  for (int k = 1; k < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({at(k, s), at(k + 1, s), at(k + 1, s + 1)});
      m.triangles.push_back({at(k, s), at(k + 1, s + 1), at(k, s + 1)});
    }
  for (int s = 0; s < segments; ++s) m.triangles.push_back({south, at(rings, s + 1), at(rings, s)});
  return m;
}

//! Closed icosphere of radius `radius`: an icosahedron subdivided `levels` times, projected to
//! the sphere; outward orientation.
inline TriMesh icosphere(int levels, double radius = 1.0) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriMesh m;
  for (const Vec3& p :
       {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t), Vec3(0, 1, t),
        Vec3(0, -1, -t), Vec3(0, 1, -t), Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)})
    m.positions.push_back(glm::normalize(p));
  m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      const int index = static_cast<int>(m.positions.size()) - 1;
      middle.emplace(key, index);
      return index;
    };
    std::vector<Tri> next;
    for (const Tri& f : m.triangles) {
      const int a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      next.push_back({f[0], a, c});
      next.push_back({f[1], b, a});
      next.push_back({f[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  for (Vec3& p : m.positions) p *= radius;
  return m;
}

//! Open cone surface: apex (vertex 0) at the origin, axis +z, half-angle `alpha`, `rings` rings
//! of `segments` vertices at slant distances k * slant / rings; outward orientation.
inline TriMesh cone(double alpha, double slant, int rings, int segments) {
  TriMesh m;
  m.positions.push_back(Vec3(0.0));
  for (int k = 1; k <= rings; ++k) {
    const double rho = slant * k / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * M_PI * s / segments;
      m.positions.push_back(Vec3(rho * std::sin(alpha) * std::cos(phi), rho * std::sin(alpha) * std::sin(phi),
                                 rho * std::cos(alpha)));
    }
  }
  const auto at = [segments](int k, int s) { return 1 + (k - 1) * segments + (s % segments); };
  // Outward for a cone opening upward: the normal points away from the axis and down.
  for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s + 1), at(1, s)});
  for (int k = 1; k < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({at(k, s), at(k, s + 1), at(k + 1, s + 1)});
      m.triangles.push_back({at(k, s), at(k + 1, s + 1), at(k + 1, s)});
    }
  return m;
}

//! Signed volume of a closed mesh (divergence theorem), independent of the library.
inline double signed_volume(const TriMesh& m) {
  double v = 0.0;
  for (const Tri& t : m.triangles)
    v += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  return v;
}

inline double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

inline double signed_area2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

//! Edge-path distances from a point on face `face` (position `origin`), by an O(V^2) Dijkstra over
//! the mesh's edges: the three corners start at their Euclidean distance from the point.
inline std::vector<double> edge_path_distances(const TriMesh& m, int face, const Vec3& origin) {
  const size_t n = m.positions.size();
  std::vector<std::vector<int>> adjacent(n);
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      adjacent[t[k]].push_back(t[(k + 1) % 3]);
      adjacent[t[(k + 1) % 3]].push_back(t[k]);
    }
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  std::vector<char> done(n, 0);
  for (int v : m.triangles[face]) d[v] = glm::distance(origin, m.positions[v]);
  for (;;) {
    int best = -1;
    for (size_t v = 0; v < n; ++v)
      if (!done[v] && std::isfinite(d[v]) && (best < 0 || d[v] < d[best])) best = static_cast<int>(v);
    if (best < 0) break;
    done[best] = 1;
    for (int w : adjacent[best])
      d[w] = std::min(d[w], d[best] + glm::distance(m.positions[best], m.positions[w]));
  }
  return d;
}

//! Faces as cyclic triples rotated to start at their smallest index (orientation kept).
inline Tri canonical_cycle(const Tri& t) {
  const int k = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

//! Vertex-connected components of the faces (union-find), one id per face.
inline std::vector<int> face_component_ids(const TriMesh& m) {
  std::vector<int> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Tri& t : m.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::map<int, int> ids;
  std::vector<int> result;
  for (const Tri& t : m.triangles)
    result.push_back(ids.emplace(find(t[0]), static_cast<int>(ids.size())).first->second);
  return result;
}

}  // namespace meshquilt::test
