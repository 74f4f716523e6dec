#pragma once
// Procedural meshes and an independent topology checker for the element-merging tests. Written
// separately from the library so that tests do not check the code against itself.

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "mesh/tri_mesh.h"

namespace meshquilt::test {

//! Closed capped tube along x from x0 to x1: `rings` circles of `sides` vertices, a fan cap at
//! each end, outward orientation. `phase` rotates the circles; `offset` translates everything.
inline TriMesh capped_tube(double x0, double x1, double radius, int rings, int sides, double phase = 0.0,
                           Vec3 offset = Vec3(0.0)) {
  TriMesh m;
  for (int i = 0; i < rings; ++i) {
    const double x = x0 + (x1 - x0) * i / (rings - 1);
    for (int k = 0; k < sides; ++k) {
      const double a = phase + 2.0 * M_PI * k / sides;
      m.positions.push_back(offset + Vec3(x, radius * std::cos(a), radius * std::sin(a)));
    }
  }
  auto id = [&](int i, int k) { return static_cast<int32_t>(i * sides + (k % sides)); };
  for (int i = 0; i + 1 < rings; ++i)
    for (int k = 0; k < sides; ++k) {
      m.triangles.push_back({id(i, k), id(i, k + 1), id(i + 1, k + 1)});
      m.triangles.push_back({id(i, k), id(i + 1, k + 1), id(i + 1, k)});
    }
  const auto c0 = static_cast<int32_t>(m.positions.size());
  m.positions.push_back(offset + Vec3(x0, 0.0, 0.0));
  const auto c1 = static_cast<int32_t>(m.positions.size());
  m.positions.push_back(offset + Vec3(x1, 0.0, 0.0));
  for (int k = 0; k < sides; ++k) {
    m.triangles.push_back({c0, id(0, k + 1), id(0, k)});
    m.triangles.push_back({c1, id(rings - 1, k), id(rings - 1, k + 1)});
  }
  return m;
}

//! Closed capped tube swept along a centreline in the x-z plane (a weave yarn): circles in the
//! plane spanned by y and the in-plane normal, outward orientation like capped_tube.
inline TriMesh swept_tube(const std::vector<Vec3>& centre, double radius, int sides, double phase = 0.0) {
  TriMesh m;
  const int rings = static_cast<int>(centre.size());
  for (int i = 0; i < rings; ++i) {
    const Vec3 d = centre[std::min(i + 1, rings - 1)] - centre[std::max(i - 1, 0)];
    const Vec3 t = d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    const Vec3 b(0.0, 1.0, 0.0);
    const Vec3 n(b.y * t.z - b.z * t.y, b.z * t.x - b.x * t.z, b.x * t.y - b.y * t.x);  // b x t
    for (int k = 0; k < sides; ++k) {
      const double a = phase + 2.0 * M_PI * k / sides;
      // At a = 0 the point is on -n ... matching capped_tube's turn from +y towards +z.
      m.positions.push_back(centre[i] + radius * (std::cos(a) * b - std::sin(a) * n));
    }
  }
  auto id = [&](int i, int k) { return static_cast<int32_t>(i * sides + (k % sides)); };
  for (int i = 0; i + 1 < rings; ++i)
    for (int k = 0; k < sides; ++k) {
      m.triangles.push_back({id(i, k), id(i, k + 1), id(i + 1, k + 1)});
      m.triangles.push_back({id(i, k), id(i + 1, k + 1), id(i + 1, k)});
    }
  const auto c0 = static_cast<int32_t>(m.positions.size());
  m.positions.push_back(centre.front());
  const auto c1 = static_cast<int32_t>(m.positions.size());
  m.positions.push_back(centre.back());
  for (int k = 0; k < sides; ++k) {
    m.triangles.push_back({c0, id(0, k + 1), id(0, k)});
    m.triangles.push_back({c1, id(rings - 1, k), id(rings - 1, k + 1)});
  }
  return m;
}

//! Centreline of an undulating yarn: x from x0 to x1, z = amplitude sin(2 pi x / wavelength).
inline std::vector<Vec3> yarn_centre(double x0, double x1, int rings, double amplitude, double wavelength,
                                     Vec3 offset = Vec3(0.0)) {
  std::vector<Vec3> c;
  for (int i = 0; i < rings; ++i) {
    const double x = x0 + (x1 - x0) * i / (rings - 1);
    c.push_back(offset + Vec3(x, 0.0, amplitude * std::sin(2.0 * M_PI * x / wavelength)));
  }
  return c;
}

//! Torus around the z axis (major radius R, minor r), outward orientation.
inline TriMesh torus(double R, double r, int nu, int nv, double phase_u = 0.0, double phase_v = 0.0) {
  TriMesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = phase_u + 2.0 * M_PI * i / nu, v = phase_v + 2.0 * M_PI * j / nv;
      m.positions.push_back(Vec3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  auto id = [&](int i, int j) { return static_cast<int32_t>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

//! Rotation about z by `angle` around `centre`.
inline void rotate_z(TriMesh& m, double angle, Vec3 centre = Vec3(0.0)) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec3& p : m.positions) {
    const Vec3 d = p - centre;
    p = centre + Vec3(c * d.x - s * d.y, s * d.x + c * d.y, d.z);
  }
}

//! Concatenation of two meshes.
inline TriMesh concat(const TriMesh& a, const TriMesh& b) {
  TriMesh m = a;
  const auto base = static_cast<int32_t>(a.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (Tri t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return m;
}

//! Signed volume (positive for a closed outward-oriented surface).
inline double signed_volume(const TriMesh& m) {
  double v = 0.0;
  for (const Tri& t : m.triangles) {
    const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    v += (a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x)) / 6.0;
  }
  return v;
}

//! What the tests check about a surface, computed by plain counting.
struct Topology {
  bool every_edge_twice_opposite = true;  // each directed edge once, its reverse once
  bool vertex_links_are_cycles = true;    // faces around each vertex form one cycle
  bool no_repeated_index = true;
  int components = 0;
  long euler = 0;
  int unused_vertices = 0;
};

inline Topology topology(const TriMesh& m) {
  Topology t;
  std::map<std::pair<int32_t, int32_t>, int> directed;
  for (const Tri& f : m.triangles) {
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) t.no_repeated_index = false;
    for (int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
  }
  std::set<std::pair<int32_t, int32_t>> undirected;
  for (const auto& [e, n] : directed) {
    const auto rev = directed.find({e.second, e.first});
    if (n != 1 || rev == directed.end() || rev->second != 1) t.every_edge_twice_opposite = false;
    undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
  }
  // Link of v: the edges (a -> b) opposite v in its faces; in a closed manifold they chain into
  // one cycle.
  std::vector<std::map<int32_t, int32_t>> link(m.positions.size());
  std::vector<int> count(m.positions.size(), 0);
  for (const Tri& f : m.triangles)
    for (int k = 0; k < 3; ++k) {
      link[f[k]][f[(k + 1) % 3]] = f[(k + 2) % 3];
      ++count[f[k]];
    }
  for (size_t v = 0; v < m.positions.size(); ++v) {
    if (count[v] == 0) {
      ++t.unused_vertices;
      continue;
    }
    if (static_cast<int>(link[v].size()) != count[v]) {
      t.vertex_links_are_cycles = false;
      continue;
    }
    int32_t start = link[v].begin()->first, x = start;
    int steps = 0;
    do {
      auto it = link[v].find(x);
      if (it == link[v].end()) break;
      x = it->second;
      ++steps;
    } while (x != start && steps <= count[v]);
    if (x != start || steps != count[v]) t.vertex_links_are_cycles = false;
  }
  std::vector<int32_t> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Tri& f : m.triangles) {
    parent[find(f[0])] = find(f[1]);
    parent[find(f[0])] = find(f[2]);
  }
  for (size_t v = 0; v < m.positions.size(); ++v)
    if (count[v] > 0 && find(static_cast<int32_t>(v)) == static_cast<int32_t>(v)) ++t.components;
  t.euler = static_cast<long>(m.positions.size() - t.unused_vertices) - static_cast<long>(undirected.size()) +
            static_cast<long>(m.triangles.size());
  return t;
}

//! Whether segment [p, q] crosses triangle (a, b, c) (plain floating point, strict interior).
inline bool segment_crosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  auto det = [](const Vec3& u, const Vec3& v, const Vec3& w) {
    return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) + u.z * (v.x * w.y - v.y * w.x);
  };
  const double sp = det(a - p, b - p, c - p), sq = det(a - q, b - q, c - q);
  // Ends within rounding of the plane (coplanar facets of a tube strip) do not cross it.
  const double eps = 1e-9 * glm::length(glm::cross(b - a, c - a)) * glm::length(q - p);
  if (std::abs(sp) <= eps || std::abs(sq) <= eps) return false;
  if (sp * sq >= 0.0) return false;  // both ends on one side of the plane
  const double s1 = det(a - p, b - p, q - p), s2 = det(b - p, c - p, q - p), s3 = det(c - p, a - p, q - p);
  return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
}

//! Number of face pairs that share no vertex and cross (brute force with a box test); the first
//! such pair goes to `first` when given.
inline int crossing_pairs(const TriMesh& m, std::pair<int, int>* first = nullptr) {
  int n = 0;
  const size_t F = m.triangles.size();
  std::vector<std::array<Vec3, 2>> box(F);
  for (size_t f = 0; f < F; ++f) {
    box[f] = {m.positions[m.triangles[f][0]], m.positions[m.triangles[f][0]]};
    for (int k = 1; k < 3; ++k) {
      const Vec3& p = m.positions[m.triangles[f][k]];
      for (int d = 0; d < 3; ++d) box[f][0][d] = std::min(box[f][0][d], p[d]), box[f][1][d] = std::max(box[f][1][d], p[d]);
    }
  }
  for (size_t f = 0; f < F; ++f)
    for (size_t g = f + 1; g < F; ++g) {
      bool apart = false;
      for (int d = 0; d < 3; ++d) apart = apart || box[f][1][d] < box[g][0][d] || box[g][1][d] < box[f][0][d];
      if (apart) continue;
      const Tri &s = m.triangles[f], &t = m.triangles[g];
      bool shares = false;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) shares = shares || s[i] == t[j];
      if (shares) continue;
      const Vec3 A[3] = {m.positions[s[0]], m.positions[s[1]], m.positions[s[2]]};
      const Vec3 B[3] = {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
      bool hit = false;
      for (int k = 0; k < 3 && !hit; ++k)
        hit = segment_crosses(A[k], A[(k + 1) % 3], B[0], B[1], B[2]) || segment_crosses(B[k], B[(k + 1) % 3], A[0], A[1], A[2]);
      if (hit && n == 0 && first) *first = {static_cast<int>(f), static_cast<int>(g)};
      n += hit;
    }
  return n;
}

}  // namespace meshquilt::test
