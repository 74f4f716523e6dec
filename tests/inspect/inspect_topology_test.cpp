// The inspect report on constructed meshes whose answers are known exactly, and against
// brute-force counts on small swatches and real meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "inspect/element_topology.h"
#include "inspect/inspect_report.h"
#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "spatial/exact_predicates.h"
#include "swatch/chainmail.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

// A closed torus: nu x nv quads split in two, around `axis_a` x `axis_b` (an orthonormal pair
// spanning the ring's plane). Vertex (i, j) sits at angle 2 pi i / nu around the ring.
TriMesh torus(const Vec3& center, const Vec3& axis_a, const Vec3& axis_b, double R, double r, int nu, int nv) {
  TriMesh m;
  const Vec3 normal = glm::cross(axis_a, axis_b);
  for (int i = 0; i < nu; ++i) {
    const double u = 2.0 * std::numbers::pi * i / nu;
    const Vec3 radial = std::cos(u) * axis_a + std::sin(u) * axis_b;
    for (int j = 0; j < nv; ++j) {
      const double v = 2.0 * std::numbers::pi * j / nv;
      m.positions.push_back(center + (R + r * std::cos(v)) * radial + r * std::sin(v) * normal);
    }
  }
  auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

TriMesh append(TriMesh a, const TriMesh& b) {
  const auto n = static_cast<int32_t>(a.positions.size());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  for (const Tri& t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  return a;
}

const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);

TEST(Inspect, TwoLinkedToriAreTwoClosedElementsWithoutIntersections) {
  // The second ring passes through the first; their centre circles stay 1 apart, tubes 0.25.
  const TriMesh m = append(torus({0, 0, 0}, X, Y, 1.0, 0.25, 48, 16), torus({1, 0, 0}, X, Z, 1.0, 0.25, 48, 16));
  const InspectReport r = inspect_mesh(m);
  EXPECT_EQ(r.faces, 2 * 48 * 16 * 2);
  EXPECT_EQ(r.vertices, 2 * 48 * 16);
  EXPECT_EQ(r.elements, 2);
  EXPECT_EQ(r.closed_elements, 2);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.nonmanifold_edges, 0);
  EXPECT_EQ(r.nonmanifold_vertices, 0);
  EXPECT_EQ(r.intersecting_face_pairs, 0);
  EXPECT_EQ(r.self_intersecting_face_pairs, 0);
}

TEST(Inspect, TwoOverlappingToriIntersect) {
  const TriMesh m = append(torus({0, 0, 0}, X, Y, 1.0, 0.25, 48, 16), torus({0.6, 0, 0.1}, X, Y, 1.0, 0.25, 48, 16));
  const InspectReport r = inspect_mesh(m);
  EXPECT_EQ(r.elements, 2);
  EXPECT_EQ(r.closed_elements, 2);
  EXPECT_GT(r.intersecting_face_pairs, 0);
  EXPECT_EQ(r.self_intersecting_face_pairs, 0);
}

TEST(Inspect, TorusWithFacesRemovedHasExactBoundary) {
  TriMesh m = torus({0, 0, 0}, X, Y, 1.0, 0.3, 32, 16);
  // Remove k faces that share no vertex (3 boundary edges each) and one whole quad (4 edges).
  std::vector<char> drop(m.num_faces(), 0);
  int k = 0;
  for (int i = 0; i < 32; i += 4) {
    for (int j = 0; j < 16; j += 4) {
      drop[2 * (i * 16 + j)] = 1;
      ++k;
    }
  }
  drop[2 * (2 * 16 + 2)] = drop[2 * (2 * 16 + 2) + 1] = 1;
  TriMesh holed;
  holed.positions = m.positions;
  for (size_t f = 0; f < m.num_faces(); ++f)
    if (!drop[f]) holed.triangles.push_back(m.triangles[f]);
  const InspectReport r = inspect_mesh(holed);
  EXPECT_EQ(r.boundary_edges, 3 * k + 4);
  EXPECT_EQ(r.nonmanifold_edges, 0);
  EXPECT_EQ(r.nonmanifold_vertices, 0);
  EXPECT_EQ(r.elements, 1);
  EXPECT_EQ(r.closed_elements, 0);
}

TEST(Inspect, BowtieHasOnePinchedVertex) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const InspectReport r = inspect_mesh(m);
  EXPECT_EQ(r.nonmanifold_vertices, 1);
  EXPECT_EQ(r.boundary_edges, 6);
  EXPECT_EQ(r.elements, 1);
  EXPECT_EQ(r.closed_elements, 0);
}

TEST(Inspect, ToriTouchingAtOneWeldedVertexAreOneOpenElement) {
  // Vertex (0, 0) of the first torus is its x-maximum (1.25, 0, 0); vertex (24, 0) of the second
  // (u = pi) is its x-minimum, placed at the same point. Separate vertex copies are welded.
  const TriMesh a = torus({0, 0, 0}, X, Y, 1.0, 0.25, 48, 16);
  const TriMesh b = torus({2.5, 0, 0}, X, Y, 1.0, 0.25, 48, 16);
  ASSERT_NEAR(glm::length(a.positions[0] - b.positions[24 * 16]), 0.0, 1e-12);
  const TriMesh m = append(a, b);
  const InspectReport r = inspect_mesh(m);
  EXPECT_EQ(r.vertices, 2 * 48 * 16 - 1);
  EXPECT_EQ(r.elements, 1);
  EXPECT_EQ(r.closed_elements, 0);
  EXPECT_EQ(r.nonmanifold_vertices, 1);
  EXPECT_EQ(r.boundary_edges, 0);
  EXPECT_EQ(r.nonmanifold_edges, 0);
  EXPECT_EQ(r.intersecting_face_pairs, 0);
  EXPECT_EQ(r.self_intersecting_face_pairs, 0);
}

TEST(Inspect, ThreeTrianglesOnOneEdge) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const InspectReport r = inspect_mesh(m);
  EXPECT_EQ(r.nonmanifold_edges, 1);
  EXPECT_EQ(r.boundary_edges, 6);
  EXPECT_EQ(r.nonmanifold_vertices, 0);
  EXPECT_EQ(r.elements, 1);
  EXPECT_EQ(r.closed_elements, 0);
}

// Brute-force references, written apart from the library: edge counts from a map of sorted
// vertex pairs, pinched vertices by walking the faces around each vertex, components by
// repeated relaxation, intersections by exhaustive edge-against-triangle tests.
struct Reference {
  int64_t boundary = 0, nonmanifold = 0, pinched = 0;
  int elements = 0, closed = 0;
  int64_t between = 0, within = 0;
};

bool ref_segment_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r) {
  const int sa = orient3d(p, q, r, a), sb = orient3d(p, q, r, b);
  if (sa * sb > 0) return false;
  if (sa == 0 && sb == 0) {
    // Coplanar (flat tops of parallel rings): in the projection along the largest normal component.
    const Vec3 n = glm::abs(glm::cross(q - p, r - p));
    const int k = n.x >= n.y && n.x >= n.z ? 0 : (n.y >= n.z ? 1 : 2);
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    auto o = [&](const Vec3& u, const Vec3& v, const Vec3& w) { return orient2d(u[i], u[j], v[i], v[j], w[i], w[j]); };
    auto inside = [&](const Vec3& x) {
      const int s1 = o(p, q, x), s2 = o(q, r, x), s3 = o(r, p, x);
      return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
    };
    if (inside(a) || inside(b)) return true;
    auto on = [&](const Vec3& u, const Vec3& v, const Vec3& x) {
      return std::min(u[i], v[i]) <= x[i] && x[i] <= std::max(u[i], v[i]) && std::min(u[j], v[j]) <= x[j] &&
             x[j] <= std::max(u[j], v[j]);
    };
    const Vec3 tri[3] = {p, q, r};
    for (int e = 0; e < 3; ++e) {
      const Vec3 &c = tri[e], &d = tri[(e + 1) % 3];
      const int o1 = o(a, b, c), o2 = o(a, b, d), o3 = o(c, d, a), o4 = o(c, d, b);
      if (o1 * o2 < 0 && o3 * o4 < 0) return true;
      if ((o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b)))
        return true;
    }
    return false;
  }
  const int s1 = orient3d(a, b, p, q), s2 = orient3d(a, b, q, r), s3 = orient3d(a, b, r, p);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

Reference brute_force(const TriMesh& m) {
  Reference ref;
  const int nf = static_cast<int>(m.num_faces());
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (int f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      const int a = m.triangles[f][i], b = m.triangles[f][(i + 1) % 3];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  // Components by label relaxation over shared vertices.
  std::vector<int> label(m.num_vertices());
  for (size_t v = 0; v < label.size(); ++v) label[v] = static_cast<int>(v);
  for (bool changed = true; changed;) {
    changed = false;
    for (const Tri& t : m.triangles) {
      const int lo = std::min({label[t[0]], label[t[1]], label[t[2]]});
      for (int32_t v : t)
        if (label[v] != lo) label[v] = lo, changed = true;
    }
  }
  std::map<int, bool> closed;
  for (const Tri& t : m.triangles) closed[label[t[0]]] = true;
  for (const auto& [e, faces] : edge_faces) {
    if (faces.size() == 1) ++ref.boundary;
    if (faces.size() > 2) ++ref.nonmanifold;
    if (faces.size() != 2) closed[label[e.first]] = false;
  }
  // Fans: faces around v, grown from a seed through edges (v, w) shared by two faces.
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    std::vector<int> around;
    for (int f = 0; f < nf; ++f)
      for (int32_t u : m.triangles[f])
        if (u == static_cast<int32_t>(v)) around.push_back(f);
    if (around.empty()) continue;
    std::vector<int> fan{around[0]};
    for (size_t k = 0; k < fan.size(); ++k) {
      for (int g : around) {
        if (std::find(fan.begin(), fan.end(), g) != fan.end()) continue;
        int shared = 0;
        for (int32_t a : m.triangles[fan[k]])
          for (int32_t b : m.triangles[g]) shared += (a == b);
        if (shared >= 2) fan.push_back(g);
      }
    }
    if (fan.size() < around.size()) {
      ++ref.pinched;
      closed[label[v]] = false;
    }
  }
  ref.elements = static_cast<int>(closed.size());
  for (const auto& [l, c] : closed) ref.closed += c;
  for (int f = 0; f < nf; ++f) {
    for (int g = f + 1; g < nf; ++g) {
      const Tri &a = m.triangles[f], &b = m.triangles[g];
      const bool same = label[a[0]] == label[b[0]];
      bool adjacent = false;
      for (int32_t u : a) adjacent |= (u == b[0] || u == b[1] || u == b[2]);
      if (adjacent) {
        // Faces of different elements never share a vertex (elements are vertex-connected).
        continue;
      }
      // Disjoint bounding boxes cannot meet; every other pair is decided exactly below.
      bool apart = false;
      for (int k = 0; k < 3; ++k) {
        const double alo = std::min({m.positions[a[0]][k], m.positions[a[1]][k], m.positions[a[2]][k]});
        const double ahi = std::max({m.positions[a[0]][k], m.positions[a[1]][k], m.positions[a[2]][k]});
        const double blo = std::min({m.positions[b[0]][k], m.positions[b[1]][k], m.positions[b[2]][k]});
        const double bhi = std::max({m.positions[b[0]][k], m.positions[b[1]][k], m.positions[b[2]][k]});
        apart |= ahi < blo || bhi < alo;
      }
      if (apart) continue;
      bool hit = false;
      for (int e = 0; e < 3 && !hit; ++e) {
        hit = ref_segment_triangle(m.positions[a[e]], m.positions[a[(e + 1) % 3]], m.positions[b[0]], m.positions[b[1]], m.positions[b[2]]) ||
              ref_segment_triangle(m.positions[b[e]], m.positions[b[(e + 1) % 3]], m.positions[a[0]], m.positions[a[1]], m.positions[a[2]]);
      }
      if (hit) ++(same ? ref.within : ref.between);
    }
  }
  return ref;
}

// The report welds its input; the reference runs on the welded mesh, which must be unchanged
// by welding again.
void expect_report_matches(const TriMesh& m, const Reference& ref) {
  ASSERT_EQ(weld_vertices(m).num_vertices(), m.num_vertices());
  const InspectReport r = inspect_mesh(m);
  EXPECT_EQ(r.elements, ref.elements);
  EXPECT_EQ(r.closed_elements, ref.closed);
  EXPECT_EQ(r.boundary_edges, ref.boundary);
  EXPECT_EQ(r.nonmanifold_edges, ref.nonmanifold);
  EXPECT_EQ(r.nonmanifold_vertices, ref.pinched);
  EXPECT_EQ(r.intersecting_face_pairs, ref.between);
  EXPECT_EQ(r.self_intersecting_face_pairs, ref.within);
}

TEST(Inspect, SmallChainmailSwatchMatchesBruteForce) {
  // A row of linked rings, two rings pushed into their neighbours, one ring folded through
  // itself (a second copy of half a ring in the same element), one ring with a hole.
  TriMesh m;
  for (int i = 0; i < 5; ++i) {
    const bool vertical = i % 2;
    m = append(m, torus({1.5 * i, 0.0, 0.0}, X, vertical ? Z : Y, 1.0, 0.2, 24, 8));
  }
  m = append(m, torus({0.3, 2.2, 0.05}, X, Y, 1.0, 0.2, 24, 8));
  m = append(m, torus({1.1, 2.2, 0.0}, X, Y, 1.0, 0.2, 24, 8));
  TriMesh folded = torus({0.0, -3.0, 0.0}, X, Y, 1.0, 0.2, 24, 8);
  const TriMesh twisted = torus({0.2, -3.0, 0.0}, X, Z, 0.8, 0.2, 24, 8);
  // Glue the twisted ring to the first through one shared vertex: one element.
  const auto n = static_cast<int32_t>(folded.positions.size());
  folded.positions.insert(folded.positions.end(), twisted.positions.begin(), twisted.positions.end());
  for (const Tri& t : twisted.triangles) folded.triangles.push_back({t[0] == 0 ? 0 : t[0] + n, t[1] == 0 ? 0 : t[1] + n, t[2] == 0 ? 0 : t[2] + n});
  m = append(m, folded);
  TriMesh holed = torus({0.0, 6.0, 0.0}, X, Y, 1.0, 0.2, 24, 8);
  holed.triangles.erase(holed.triangles.begin() + 10, holed.triangles.begin() + 13);
  m = append(m, holed);
  m = weld_vertices(m);
  const Reference ref = brute_force(m);
  EXPECT_GT(ref.between, 0);
  EXPECT_GT(ref.within, 0);
  EXPECT_GT(ref.boundary, 0);
  expect_report_matches(m, ref);
}

TEST(Inspect, RealMeshesMatchBruteForce) {
  const auto dir = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data" / "meshes";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared meshes not available";
  for (const char* name : {"sphere.off", "cylinder.off", "knot.off"}) {
    SCOPED_TRACE(name);
    TriMesh m = weld_vertices(read_mesh(dir / name));
    m.elements.clear();
    // The first faces only: the brute force is quadratic. Cutting makes boundaries and may pinch.
    if (m.num_faces() > 1200) m.triangles.resize(1200);
    m = weld_vertices(m);  // drops the vertices no kept face uses
    expect_report_matches(m, brute_force(m));
  }
}

TEST(Inspect, GeneratedSwatchesMatchBruteForce) {
  // The project's own swatches: chain mail rings are closed, linked and do not touch.
  const TriMesh mail = weld_vertices(make_chainmail(ChainmailOptions::small()));
  const Reference ref = brute_force(mail);
  EXPECT_EQ(ref.elements, 8);
  EXPECT_EQ(ref.closed, 8);
  EXPECT_EQ(ref.between, 0);
  expect_report_matches(mail, ref);
  const TriMesh weave = weld_vertices(make_weave(WeaveOptions::small()));
  expect_report_matches(weave, brute_force(weave));
}

TEST(ElementTopology, FaceElementsAreTheComponents) {
  const TriMesh m = append(append(torus({0, 0, 0}, X, Y, 1.0, 0.25, 12, 6), torus({5, 0, 0}, X, Y, 1.0, 0.25, 12, 6)),
                           torus({10, 0, 0}, X, Y, 1.0, 0.25, 12, 6));
  const ElementTopology t = element_topology(m);
  ASSERT_EQ(t.elements, 3);
  for (size_t f = 0; f < m.num_faces(); ++f) EXPECT_EQ(t.face_element[f], static_cast<int32_t>(f / 144));
}

}  // namespace
}  // namespace meshquilt
