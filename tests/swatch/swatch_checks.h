#pragma once
// Checks of a swatch written independently of the generators: components, element topology,
// intersections by brute-force exact tests, what quilting needs of a swatch, and round trips
// through our reader and OpenMesh.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <optional>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/swatch_frame.h"
#include "swatch/chainmail.h"
#include "swatch/fruit.h"
#include "swatch/heightfield.h"
#include "swatch/nuts.h"
#include "swatch/weave.h"

namespace meshquilt::swatch_checks {

namespace fs = std::filesystem;

inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("meshquilt_swatch_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// Independent checks.

struct Box {
  Vec3 lo{INFINITY}, hi{-INFINITY};
  void add(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Vec3 extent() const { return hi - lo; }
};

inline Box bounds(const TriMesh& m) {
  Box b;
  for (const Vec3& p : m.positions) b.add(p);
  return b;
}

// Vertex-connected components by union-find.
inline int count_components(const TriMesh& m) {
  std::vector<int> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<bool> used(m.positions.size(), false);
  for (const Tri& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      parent[find(t[k])] = find(t[(k + 1) % 3]);
    }
  }
  int count = 0;
  for (size_t v = 0; v < parent.size(); ++v) count += used[v] && find(static_cast<int>(v)) == static_cast<int>(v);
  return count;
}

struct ElementTopology {
  int boundary_edges = 0;
  int nonmanifold_edges = 0;
  int misoriented_edges = 0;  // used twice in the same direction
  int euler = 0;              // V - E + F
  double volume = 0.0;        // signed, divergence theorem
};

inline std::map<int32_t, ElementTopology> element_topology(const TriMesh& m) {
  std::map<int32_t, std::map<std::pair<int32_t, int32_t>, std::pair<int, int>>> edges;  // (forward, backward) uses
  std::map<int32_t, std::vector<bool>> vertices;
  std::map<int32_t, ElementTopology> result;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const int32_t e = m.elements[f];
    const Tri& t = m.triangles[f];
    auto& used = vertices[e];
    used.resize(m.positions.size(), false);
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      const int32_t a = t[k], b = t[(k + 1) % 3];
      auto& uses = edges[e][{std::min(a, b), std::max(a, b)}];
      (a < b ? uses.first : uses.second)++;
    }
    result[e].volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
    result[e].euler += 1;
  }
  for (auto& [e, map] : edges) {
    ElementTopology& r = result[e];
    for (const auto& [edge, uses] : map) {
      const int total = uses.first + uses.second;
      r.boundary_edges += total == 1;
      r.nonmanifold_edges += total > 2;
      r.misoriented_edges += uses.first > 1 || uses.second > 1;
    }
    r.euler += static_cast<int>(std::count(vertices[e].begin(), vertices[e].end(), true)) - static_cast<int>(map.size());
  }
  return result;
}

inline double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return glm::dot(b - a, glm::cross(c - a, d - a));
}

inline int sign(double x) { return (x > 0.0) - (x < 0.0); }

// Segment pq against triangle abc, closed sets: touching counts as intersecting.
inline bool segment_hits_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int sp = sign(orient(a, b, c, p)), sq = sign(orient(a, b, c, q));
  if (sp != 0 && sp == sq) return false;
  if (sp == 0 && sq == 0) {
    // Coplanar: conservatively report contact when the segment meets the triangle's bbox; our
    // swatches never get here unless something is badly wrong.
    return true;
  }
  const int s1 = sign(orient(p, q, a, b)), s2 = sign(orient(p, q, b, c)), s3 = sign(orient(p, q, c, a));
  const bool has_pos = s1 > 0 || s2 > 0 || s3 > 0, has_neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(has_pos && has_neg);
}

inline bool triangles_intersect(const TriMesh& m, const Tri& s, const Tri& t) {
  const auto& P = m.positions;
  for (int k = 0; k < 3; ++k) {
    if (segment_hits_triangle(P[s[k]], P[s[(k + 1) % 3]], P[t[0]], P[t[1]], P[t[2]])) return true;
    if (segment_hits_triangle(P[t[k]], P[t[(k + 1) % 3]], P[s[0]], P[s[1]], P[s[2]])) return true;
  }
  return false;
}

// Pairs of faces of different elements that intersect or touch: sweep over x of face bboxes,
// then y/z bbox overlap, then the exact edge-against-triangle test both ways.
inline int intersecting_pairs(const TriMesh& m) {
  const size_t n = m.triangles.size();
  std::vector<Box> box(n);
  for (size_t f = 0; f < n; ++f) {
    for (int k = 0; k < 3; ++k) box[f].add(m.positions[m.triangles[f][k]]);
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return box[a].lo.x < box[b].lo.x; });
  int count = 0;
  for (size_t i = 0; i < n; ++i) {
    const Box& a = box[order[i]];
    for (size_t j = i + 1; j < n && box[order[j]].lo.x <= a.hi.x; ++j) {
      const Box& b = box[order[j]];
      if (m.elements[order[i]] == m.elements[order[j]]) continue;
      if (b.lo.y > a.hi.y || a.lo.y > b.hi.y || b.lo.z > a.hi.z || a.lo.z > b.hi.z) continue;
      count += triangles_intersect(m, m.triangles[order[i]], m.triangles[order[j]]);
    }
  }
  return count;
}

inline double smallest_area(const TriMesh& m) {
  double smallest = INFINITY;
  for (const Tri& t : m.triangles) {
    const auto& P = m.positions;
    smallest = std::min(smallest, 0.5 * glm::length(glm::cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]])));
  }
  return smallest;
}

// ---------------------------------------------------------------------------------------------
// The common body: one swatch, what every kind must satisfy.

struct Design {
  int elements;
  bool closed;
  int euler;  // of each element: 0 for a ring or a nut, 2 for a sphere-like element
};

inline void check_swatch(const TriMesh& m, const Design& design, const std::string& name) {
  SCOPED_TRACE(name);
  ASSERT_EQ(m.elements.size(), m.triangles.size());
  // Elements: as designed, numbered 0..n-1, each exactly one connected component.
  EXPECT_EQ(count_components(m), design.elements);
  std::vector<int32_t> ids(m.elements);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  ASSERT_EQ(static_cast<int>(ids.size()), design.elements);
  EXPECT_EQ(ids.front(), 0);
  EXPECT_EQ(ids.back(), design.elements - 1);

  const Box box = bounds(m);
  const Vec3 e = box.extent();
  EXPECT_LT(e.z, e.x);
  EXPECT_LT(e.z, e.y);
  EXPECT_GT(smallest_area(m), 1e-8 * glm::dot(e, e)) << "degenerate triangle";

  for (const auto& [element, topo] : element_topology(m)) {
    SCOPED_TRACE("element " + std::to_string(element));
    EXPECT_EQ(topo.nonmanifold_edges, 0);
    EXPECT_EQ(topo.misoriented_edges, 0);
    if (design.closed) {
      EXPECT_EQ(topo.boundary_edges, 0);
      EXPECT_EQ(topo.euler, design.euler);
      EXPECT_GT(topo.volume, 0.0);
    }
  }
  EXPECT_EQ(intersecting_pairs(m), 0);
  // The quilting's swatch loader accepts it as it is: no turn, only a shift to the origin.
  const TriMesh framed = orient_swatch(m, name);
  ASSERT_EQ(framed.positions.size(), m.positions.size());
  for (size_t v = 0; v < m.positions.size(); v += 97) {
    EXPECT_NEAR(glm::length(framed.positions[v] - (m.positions[v] - box.lo)), 0.0, 1e-9 * glm::length(e));
  }
}

// Writes the swatch, reads it back with our reader and with OpenMesh, and compares.
inline void check_round_trip(const TriMesh& m, const std::string& name) {
  SCOPED_TRACE(name);
  const fs::path dir = scratch(name);
  const fs::path ply = dir / (name + ".ply");
  write_mesh(m, ply);
  const TriMesh back = read_mesh(ply);
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.elements, m.elements);

  const fs::path off = dir / (name + ".off");
  write_mesh(m, off);
  for (const fs::path& file : {ply, off}) {
    OpenMesh::TriMesh_ArrayKernelT<> reference;
    OpenMesh::IO::Options options;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(reference, file.string(), options)) << file;
    // OpenMesh drops any face that would make a vertex or edge non-manifold: all must survive.
    EXPECT_EQ(reference.n_faces(), m.triangles.size()) << file;
    EXPECT_EQ(reference.n_vertices(), m.positions.size()) << file;
    size_t boundary = 0;
    for (auto edge : reference.edges()) boundary += reference.is_boundary(edge);
    if (name.find("open") == std::string::npos) {
      EXPECT_EQ(boundary, 0u) << file;
    }
  }
  fs::remove_all(dir);
}


// The error kind `f` throws, if any (its message one line).
inline std::optional<ErrorKind> error_code(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one-line message";
    return e.kind();
  }
  return std::nullopt;
}


// The size checks are sound: swatches at the edge of what they accept still do not intersect.
template <class Options, class Make>
Options at_acceptance_limit(Options o, double Options::*field, double accepted, double rejected, Make make) {
  for (int it = 0; it < 20; ++it) {
    const double mid = 0.5 * (accepted + rejected);
    o.*field = mid;
    bool ok = true;
    try {
      make(o);
    } catch (const InputError&) {
      ok = false;
    }
    (ok ? accepted : rejected) = mid;
  }
  o.*field = accepted;
  return o;
}

}  // namespace meshquilt::swatch_checks
