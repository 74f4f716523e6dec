// Welding, components and surface defects, against constructed answers and brute-force references written here.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "core/error.h"
#include "mesh/topology.h"

namespace meshquilt {
namespace {

TriMesh tetrahedron(const Vec3& origin) {
  TriMesh m;
  m.positions = {origin, origin + Vec3(1, 0, 0), origin + Vec3(0, 1, 0), origin + Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// Signed volume by the divergence theorem; +1 for a unit cube with outward faces.
double signed_volume(const TriMesh& m) {
  double volume = 0.0;
  for (const Tri& t : m.triangles) {
    volume += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]])) / 6.0;
  }
  return volume;
}

// Unit cube, 12 outward triangles, every triangle with its own three vertex copies.
TriMesh cube_soup(double jitter, unsigned seed) {
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const Tri faces[12] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                         {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> noise(-jitter, jitter);
  TriMesh m;
  for (const Tri& f : faces) {
    Tri t;
    for (int c = 0; c < 3; ++c) {
      t[c] = static_cast<int32_t>(m.positions.size());
      m.positions.push_back(corners[f[c]] + Vec3(noise(random), noise(random), noise(random)));
    }
    m.triangles.push_back(t);
  }
  return m;
}

TEST(Topology, CubeSoupWeldsToEightVerticesAndOneComponent) {
  const TriMesh soup = cube_soup(1e-8, 1);
  int32_t count = 0;
  face_components(soup, &count);
  EXPECT_EQ(count, 12);
  const TriMesh welded = weld_vertices(soup);  // tolerance 1e-6 x sqrt(3) > jitter
  EXPECT_EQ(welded.positions.size(), 8u);
  EXPECT_EQ(welded.triangles.size(), 12u);
  const std::vector<int32_t> components = face_components(welded, &count);
  EXPECT_EQ(count, 1);
  EXPECT_EQ(components, std::vector<int32_t>(12, 0));
  EXPECT_NEAR(signed_volume(welded), 1.0, 1e-6);
  // Each surviving vertex is the first copy of its corner in input order.
  for (size_t f = 0; f < 12; ++f) {
    for (int c = 0; c < 3; ++c) {
      const Vec3 original = soup.positions[soup.triangles[f][c]];
      EXPECT_LT(glm::length(welded.positions[welded.triangles[f][c]] - original), 4e-8);
    }
  }
  EXPECT_EQ(welded.positions[0], soup.positions[0]);
}

TEST(Topology, ToleranceIsRelativeToTheDiagonalAndExact) {
  // Diagonal 100 (a 60 x 80 box): tolerance 1e-3 relative is 0.1 absolute.
  TriMesh m;
  m.positions = {{0, 0, 0}, {60, 80, 0}, {10, 10, 0}, {10.099, 10, 0}, {20, 20, 0}, {20.101, 20, 0}, {30, 0, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 6}, {5, 6, 0}};
  const TriMesh w = weld_vertices(m, 1e-3);
  // 3 joins 2 (0.099 apart); 5 stays apart from 4 (0.101 apart).
  ASSERT_EQ(w.positions.size(), 6u);
  EXPECT_EQ(w.triangles[1][0], w.triangles[0][2]);
  EXPECT_NE(w.triangles[2][0], w.triangles[1][1]);
  // Zero tolerance merges exact duplicates only.
  TriMesh d = m;
  d.positions.push_back({30, 0, 0});
  d.triangles.push_back({7, 0, 1});
  EXPECT_EQ(weld_vertices(d, 0.0).positions.size(), 7u);
}

TEST(Topology, WeldRejectsNonFinitePositions) {
  TriMesh m = tetrahedron({0, 0, 0});
  m.positions[2].y = std::numeric_limits<double>::infinity();
  EXPECT_THROW(weld_vertices(m), InputError);
}

TEST(Topology, WeldDropsDegenerateFacesAndUnusedVerticesKeepingElements) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-9, 0, 0}, {9, 9, 9}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}, {0, 3, 2}, {1, 2, 5}};  // face 1 collapses (3 joins 0); vertex 4 unused
  m.elements = {4, 5, 6};
  const TriMesh w = weld_vertices(m);
  EXPECT_EQ(w.positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  EXPECT_EQ(w.triangles, (std::vector<Tri>{{0, 1, 2}, {1, 2, 3}}));
  EXPECT_EQ(w.elements, (std::vector<int32_t>{4, 6}));
}

// Random clusters of near-coincident points, well apart from each other: the welded mesh must
// equal the brute-force answer (each vertex becomes the first member of its cluster).
TEST(Topology, WeldMatchesBruteForceOnRandomClusters) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TriMesh m;
  std::vector<Vec3> centres = {{0, 0, 0}, {1, 1, 1}};  // pin the diagonal to sqrt(3), up to jitter
  while (centres.size() < 152) {
    const Vec3 c(unit(random), unit(random), unit(random));
    bool far = true;
    for (const Vec3& o : centres) far &= glm::length(o - c) > 0.01;
    if (far) centres.push_back(c);
  }
  const double tolerance = 1e-4;  // relative; absolute about 1.7e-4
  std::vector<int> cluster_of;
  for (int copy = 0; copy < 3; ++copy) {
    for (size_t c = 0; c < centres.size(); ++c) {
      if (copy > 0 && random() % 2) continue;
      const Vec3 offset = Vec3(unit(random), unit(random), unit(random)) * 2e-5;  // well under tolerance / 2
      m.positions.push_back(centres[c] + offset);
      cluster_of.push_back(static_cast<int>(c));
    }
  }
  std::uniform_int_distribution<int32_t> pick(0, static_cast<int32_t>(m.positions.size()) - 1);
  for (int f = 0; f < 400; ++f) {
    m.triangles.push_back({pick(random), pick(random), pick(random)});
    m.elements.push_back(f % 5);
  }

  // Brute force.
  std::vector<int> first_of_cluster(centres.size(), -1);
  for (size_t v = 0; v < m.positions.size(); ++v) {
    if (first_of_cluster[cluster_of[v]] < 0) first_of_cluster[cluster_of[v]] = static_cast<int>(v);
  }
  std::vector<std::array<Vec3, 3>> expected_faces;
  std::vector<int32_t> expected_elements;
  std::set<int> used_clusters;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const Tri& t = m.triangles[f];
    const int a = cluster_of[t[0]], b = cluster_of[t[1]], c = cluster_of[t[2]];
    if (a == b || b == c || a == c) continue;
    expected_faces.push_back({m.positions[first_of_cluster[a]], m.positions[first_of_cluster[b]],
                              m.positions[first_of_cluster[c]]});
    expected_elements.push_back(m.elements[f]);
    used_clusters.insert({a, b, c});
  }

  const TriMesh w = weld_vertices(m, tolerance);
  EXPECT_EQ(w.positions.size(), used_clusters.size());
  ASSERT_EQ(w.triangles.size(), expected_faces.size());
  for (size_t f = 0; f < expected_faces.size(); ++f) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(w.positions[w.triangles[f][c]], expected_faces[f][c]);
  }
  EXPECT_EQ(w.elements, expected_elements);
  // Surviving vertices keep their input order.
  std::vector<int> order;
  for (const Vec3& p : w.positions) {
    order.push_back(static_cast<int>(std::find(m.positions.begin(), m.positions.end(), p) - m.positions.begin()));
  }
  EXPECT_TRUE(std::is_sorted(order.begin(), order.end()));
  // Deterministic.
  const TriMesh again = weld_vertices(m, tolerance);
  EXPECT_EQ(again.positions, w.positions);
  EXPECT_EQ(again.triangles, w.triangles);
}

TEST(Topology, TwoTetrahedraAreTwoComponentsNumberedByFirstFace) {
  TriMesh a = tetrahedron({0, 0, 0});
  const TriMesh b = tetrahedron({5, 0, 0});
  // Interleave the faces: b's first face comes first.
  TriMesh m;
  m.positions = a.positions;
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (int i = 0; i < 4; ++i) {
    const Tri& tb = b.triangles[i];
    m.triangles.push_back({tb[0] + 4, tb[1] + 4, tb[2] + 4});
    m.triangles.push_back(a.triangles[i]);
  }
  int32_t count = 0;
  const std::vector<int32_t> ids = face_components(m, &count);
  EXPECT_EQ(count, 2);
  EXPECT_EQ(ids, (std::vector<int32_t>{0, 1, 0, 1, 0, 1, 0, 1}));
}

// Flood fill over faces sharing a vertex, numbered by first face: the reference partition.
std::vector<int32_t> brute_force_components(const TriMesh& m) {
  std::vector<int32_t> id(m.triangles.size(), -1);
  int32_t next = 0;
  for (size_t seed = 0; seed < m.triangles.size(); ++seed) {
    if (id[seed] >= 0) continue;
    id[seed] = next;
    std::vector<size_t> stack = {seed};
    while (!stack.empty()) {
      const size_t f = stack.back();
      stack.pop_back();
      for (size_t g = 0; g < m.triangles.size(); ++g) {
        if (id[g] >= 0) continue;
        bool shares = false;
        for (int32_t u : m.triangles[f]) {
          for (int32_t v : m.triangles[g]) shares |= u == v;
        }
        if (shares) {
          id[g] = next;
          stack.push_back(g);
        }
      }
    }
    ++next;
  }
  return id;
}

TEST(Topology, ComponentsMatchFloodFill) {
  std::mt19937 random(3);
  TriMesh m;
  m.positions.resize(400, Vec3(0.0));
  std::uniform_int_distribution<int32_t> pick(0, 399);
  for (int f = 0; f < 100; ++f) m.triangles.push_back({pick(random), pick(random), pick(random)});
  int32_t count = 0;
  const std::vector<int32_t> ids = face_components(m, &count);
  const std::vector<int32_t> expected = brute_force_components(m);
  EXPECT_EQ(ids, expected);
  EXPECT_EQ(count, *std::max_element(expected.begin(), expected.end()) + 1);
  EXPECT_GT(count, 5);  // the random mesh really has several components
}

TEST(Topology, SplitByElementIdsAndJoinBack) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 2, 2}, {3, 2, 2}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}, {3, 4, 5}, {2, 4, 5}};
  m.elements = {5, 2, 5, 2};  // ids with a gap; ids need not follow connectivity
  const std::vector<TriMesh> parts = split_elements(m);
  ASSERT_EQ(parts.size(), 2u);
  // id 2: faces 1 and 3, vertices 1 2 3 4 5.
  EXPECT_EQ(parts[0].positions, (std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 2, 2}, {3, 2, 2}}));
  EXPECT_EQ(parts[0].triangles, (std::vector<Tri>{{0, 2, 1}, {1, 3, 4}}));
  // id 5: faces 0 and 2, vertices 0 1 2 3 4 5.
  EXPECT_EQ(parts[1].positions.size(), 6u);
  EXPECT_EQ(parts[1].triangles, (std::vector<Tri>{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_TRUE(parts[0].elements.empty());

  const TriMesh joined = join_elements(parts);
  EXPECT_EQ(joined.positions.size(), 11u);
  EXPECT_EQ(joined.triangles, (std::vector<Tri>{{0, 2, 1}, {1, 3, 4}, {5, 6, 7}, {8, 9, 10}}));
  EXPECT_EQ(joined.elements, (std::vector<int32_t>{0, 0, 1, 1}));
  const std::vector<TriMesh> again = split_elements(joined);
  ASSERT_EQ(again.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(again[i].positions, parts[i].positions);
    EXPECT_EQ(again[i].triangles, parts[i].triangles);
  }
}

TEST(Topology, SplitWithoutElementsUsesComponents) {
  TriMesh m = tetrahedron({0, 0, 0});
  const TriMesh b = tetrahedron({3, 0, 0});
  for (const Vec3& p : b.positions) m.positions.push_back(p);
  for (const Tri& t : b.triangles) m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  m.positions.push_back({100, 100, 100});  // unreferenced: belongs to no part
  const std::vector<TriMesh> parts = split_elements(m);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[1].positions, b.positions);
  EXPECT_EQ(parts[1].triangles, b.triangles);
  EXPECT_NEAR(signed_volume(parts[0]), 1.0 / 6.0, 1e-15);
}

// Random face soups over a few vertices (repeated and reversed edges, faces repeating a vertex),
// against counts from a map of directed edges and fans grown face by face.
TEST(Topology, SurfaceDefectsMatchBruteForceOnRandomSoups) {
  std::mt19937 random(7);
  int64_t seen_misoriented = 0, seen_nonmanifold = 0, seen_pinched = 0;
  for (int round = 0; round < 300; ++round) {
    const int vertices = 4 + round % 9;
    std::uniform_int_distribution<int32_t> vertex(0, vertices - 1);
    TriMesh m;
    m.positions.assign(static_cast<size_t>(vertices) + 2, Vec3(0.0));  // the last two unused
    const int faces = 1 + round % 14;
    for (int f = 0; f < faces; ++f) {
      Tri t{vertex(random), vertex(random), vertex(random)};
      if (random() % 4 != 0)  // mostly proper faces
        while (t[1] == t[0] || t[2] == t[0] || t[2] == t[1]) t = {vertex(random), vertex(random), vertex(random)};
      m.triangles.push_back(t);
    }
    std::map<std::pair<int32_t, int32_t>, int64_t> directed;
    int64_t degenerate = 0;
    for (const Tri& t : m.triangles) {
      degenerate += t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
      for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    }
    int64_t boundary = 0, nonmanifold = 0, misoriented = 0, edges = 0;
    for (const auto& [e, n] : directed) {
      if (e.first > e.second && directed.count({e.second, e.first})) continue;  // counted from the other side
      const int64_t back = e.first == e.second ? 0 : (directed.count({e.second, e.first}) ? directed[{e.second, e.first}] : 0);
      ++edges;
      if (n + back == 1) ++boundary;
      else if (n + back > 2) ++nonmanifold;
      else if (!(n == 1 && back == 1)) ++misoriented;
    }
    int64_t pinched = 0, used = 0;
    for (int32_t v = 0; v < static_cast<int32_t>(m.positions.size()); ++v) {
      std::vector<size_t> around;
      for (size_t f = 0; f < m.triangles.size(); ++f)
        if (std::count(m.triangles[f].begin(), m.triangles[f].end(), v) > 0) around.push_back(f);
      if (around.empty()) continue;
      ++used;
      std::vector<size_t> fan{around[0]};
      for (size_t k = 0; k < fan.size(); ++k)
        for (size_t g : around) {
          if (std::find(fan.begin(), fan.end(), g) != fan.end()) continue;
          int shared = 0;
          for (int32_t a : m.triangles[fan[k]])
            for (int32_t b : m.triangles[g]) shared += a == b;
          if (shared >= 2) fan.push_back(g);
        }
      pinched += fan.size() < around.size();
    }
    const SurfaceReport r = inspect_surface(m);
    SCOPED_TRACE(round);
    EXPECT_EQ(r.boundary_edges, boundary);
    EXPECT_EQ(r.nonmanifold_edges, nonmanifold);
    EXPECT_EQ(r.misoriented_edges, misoriented);
    EXPECT_EQ(r.degenerate_faces, degenerate);
    EXPECT_EQ(r.pinched_vertices, pinched);
    EXPECT_EQ(r.euler, used - edges + static_cast<int64_t>(m.triangles.size()));
    seen_misoriented += misoriented;
    seen_nonmanifold += nonmanifold;
    seen_pinched += pinched;
  }
  EXPECT_GT(seen_misoriented, 0);
  EXPECT_GT(seen_nonmanifold, 0);
  EXPECT_GT(seen_pinched, 0);
}

}  // namespace
}  // namespace meshquilt
