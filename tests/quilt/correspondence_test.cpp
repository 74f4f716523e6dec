#include "quilt/correspondence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/mesh_io.h"
#include "support/bumpy_sphere.h"

namespace meshquilt {
namespace {

// ---- fixtures -------------------------------------------------------------------------------

TriMesh sphere(int rings, int segments, double radius, Vec3 centre, uint32_t seed, bool flip = false) {
  return test::bumpy_sphere(rings, segments, radius, centre, seed, 0.08, flip);
}

// A flat n x n grid of unit cells at height z, facing +z (or -z when `down`).
TriMesh plane(int n, double z, bool down = false, Vec3 offset = Vec3(0.0)) {
  TriMesh m;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) m.positions.push_back(offset + Vec3(x, y, z));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  if (down)
    for (Tri& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// ---- independent reference ------------------------------------------------------------------

// Closest point on a triangle: the plane projection when it falls inside, else the best of the
// three clamped segment projections (a different method from the region test under test).
Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double l2 = glm::dot(d, d);
  const double t = l2 > 0 ? std::clamp(glm::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
  return a + t * d;
}
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - a, r = p - a;
  const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
  const double det = d00 * d11 - d01 * d01;
  if (det > 1e-300) {
    const double r0 = glm::dot(r, e0), r1 = glm::dot(r, e1);
    const double u = (d11 * r0 - d01 * r1) / det, v = (d00 * r1 - d01 * r0) / det;
    if (u >= 0 && v >= 0 && u + v <= 1) return a + u * e0 + v * e1;
  }
  Vec3 best = closest_on_segment(p, a, b);
  for (const Vec3& q : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)})
    if (glm::length(q - p) < glm::length(best - p)) best = q;
  return best;
}

Vec3 face_normal(const TriMesh& m, int f) {
  const Tri& t = m.triangles[f];
  const Vec3 n = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
  return glm::length(n) > 0 ? glm::normalize(n) : Vec3(0.0);
}

Vec3 vertex_normal(const TriMesh& m, int v) {
  Vec3 n(0.0);
  for (const Tri& t : m.triangles)
    if (t[0] == v || t[1] == v || t[2] == v)
      n += glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
  return glm::length(n) > 0 ? glm::normalize(n) : Vec3(0.0);
}

double eq1(const Vec3& p, const Vec3& n, const TriMesh& m, int f, double lambda) {
  const Tri& t = m.triangles[f];
  const Vec3 q = closest_on_triangle(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
  return (1 + lambda * glm::length(q - p)) * (1 + glm::length(n - face_normal(m, f)));
}

double mean_edge_length_near(const TriMesh& m, int f) {
  const Tri& t = m.triangles[f];
  std::set<std::pair<int, int>> edges;
  for (const Tri& u : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = u[k], b = u[(k + 1) % 3];
      const bool touches = a == t[0] || a == t[1] || a == t[2] || b == t[0] || b == t[1] || b == t[2];
      if (touches) edges.insert({std::min(a, b), std::max(a, b)});
    }
  double sum = 0;
  for (auto [a, b] : edges) sum += glm::length(m.positions[a] - m.positions[b]);
  return sum / edges.size();
}

// Separating-axis test for two projected, non-degenerate triangles (closed: touching overlaps).
bool sat_overlap(const Vec3 a[3], const Vec3 b[3]) {
  for (const Vec3* tri : {a, b})
    for (int k = 0; k < 3; ++k) {
      const double nx = -(tri[(k + 1) % 3].y - tri[k].y), ny = tri[(k + 1) % 3].x - tri[k].x;
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (int i = 0; i < 3; ++i) {
        const double pa = nx * a[i].x + ny * a[i].y, pb = nx * b[i].x + ny * b[i].y;
        amin = std::min(amin, pa), amax = std::max(amax, pa), bmin = std::min(bmin, pb), bmax = std::max(bmax, pb);
      }
      if (amax < bmin || bmax < amin) return false;
    }
  return true;
}

bool brute_projections_overlap(const TriMesh& a, const TriMesh& b) {
  for (const Tri& s : a.triangles)
    for (const Tri& t : b.triangles) {
      const Vec3 pa[3] = {a.positions[s[0]], a.positions[s[1]], a.positions[s[2]]};
      const Vec3 pb[3] = {b.positions[t[0]], b.positions[t[1]], b.positions[t[2]]};
      if (sat_overlap(pa, pb)) return true;
    }
  return false;
}

// (out_element, out_vertex, in_element, in_face)
using Key = std::tuple<int, int, int, int>;

struct Reference {
  std::set<Key> survivors;
  int pruned_a = 0, pruned_b = 0, pruned_c = 0;
  std::map<std::pair<int, int>, int> relation_sizes;
  // Each queried vertex: the minimum D and the second smallest (to recognise ties).
  std::map<std::pair<int, int>, std::pair<double, double>> best_costs;
};

Reference brute_force(const std::vector<TriMesh>& outs, const std::vector<TriMesh>& ins,
                      const std::function<bool(const Vec3&)>& in_overlap, const CorrespondenceOptions& o) {
  Reference ref;
  std::vector<Key> after_ab;
  for (int e = 0; e < int(outs.size()); ++e) {
    for (int v = 0; v < int(outs[e].positions.size()); ++v) {
      const Vec3 p = outs[e].positions[v];
      if (!in_overlap(p)) continue;
      const Vec3 n = vertex_normal(outs[e], v);
      double best = 1e300, second = 1e300;
      int best_e = -1, best_f = -1;
      for (int i = 0; i < int(ins.size()); ++i)
        for (int f = 0; f < int(ins[i].triangles.size()); ++f) {
          const double d = eq1(p, n, ins[i], f, o.lambda);
          if (d < best) {
            second = best, best = d, best_e = i, best_f = f;
          } else {
            second = std::min(second, d);
          }
        }
      ref.best_costs[{e, v}] = {best, second};
      const Tri& t = ins[best_e].triangles[best_f];
      const Vec3& a = ins[best_e].positions[t[0]];
      const double dist = glm::length(closest_on_triangle(p, a, ins[best_e].positions[t[1]], ins[best_e].positions[t[2]]) - p);
      if (glm::dot(n, face_normal(ins[best_e], best_f)) < 0) {  // (a)
        ++ref.pruned_a;
        continue;
      }
      if (dist > o.max_distance_factor * mean_edge_length_near(ins[best_e], best_f)) {  // (b)
        ++ref.pruned_b;
        continue;
      }
      after_ab.emplace_back(e, v, best_e, best_f);
    }
  }
  std::map<std::pair<int, int>, bool> overlaps;
  for (const Key& k : after_ab) {
    const auto rel = std::make_pair(std::get<0>(k), std::get<2>(k));
    if (!overlaps.count(rel)) overlaps[rel] = brute_projections_overlap(outs[rel.first], ins[rel.second]);
    if (!overlaps[rel]) {  // (c)
      ++ref.pruned_c;
      continue;
    }
    ref.survivors.insert(k);
    ++ref.relation_sizes[rel];
  }
  return ref;
}

// Checks the structure of a result and compares it with the reference, allowing a different
// face only where the reference minimum is tied (within 1e-12).
void expect_matches_reference(const Correspondences& c, const std::vector<TriMesh>& outs,
                              const std::vector<TriMesh>& ins, const std::function<bool(const Vec3&)>& in_overlap,
                              const CorrespondenceOptions& o, Reference* reference = nullptr) {
  const Reference ref = brute_force(outs, ins, in_overlap, o);
  if (reference) *reference = ref;
  std::set<Key> got;
  int ties = 0;
  for (const VertexFacePair& p : c.pairs) {
    // Pair data agrees with an independent evaluation.
    const TriMesh& in = ins[p.in_element];
    const Tri& t = in.triangles[p.in_face];
    const Vec3 v = outs[p.out_element].positions[p.out_vertex];
    const Vec3 q = closest_on_triangle(v, in.positions[t[0]], in.positions[t[1]], in.positions[t[2]]);
    EXPECT_LE(glm::length(p.closest - q), 1e-9);
    EXPECT_NEAR(p.distance, glm::length(q - v), 1e-9);
    const Vec3 h = p.barycentric.x * in.positions[t[0]] + p.barycentric.y * in.positions[t[1]] +
                   p.barycentric.z * in.positions[t[2]];
    EXPECT_LE(glm::length(h - p.closest), 1e-9);
    EXPECT_NEAR(p.barycentric.x + p.barycentric.y + p.barycentric.z, 1.0, 1e-9);
    // Its face attains the brute-force minimum of Eq. 1.
    const auto [best, second] = ref.best_costs.at({p.out_element, p.out_vertex});
    EXPECT_NEAR(eq1(v, vertex_normal(outs[p.out_element], p.out_vertex), in, p.in_face, o.lambda), best, 1e-9);
    Key k{p.out_element, p.out_vertex, p.in_element, p.in_face};
    if (!ref.survivors.count(k) && second - best < 1e-12) ++ties;
    got.insert(k);
  }
  EXPECT_EQ(ties, 0);
  EXPECT_EQ(got, ref.survivors);
  EXPECT_EQ(got.size(), c.pairs.size());  // no duplicates

  // Relations: exactly the reference's, each pair in exactly one, sorted as documented.
  std::map<std::pair<int, int>, int> sizes;
  std::vector<int> seen(c.pairs.size(), 0);
  for (const ElementRelation& r : c.relations) {
    sizes[{r.out_element, r.in_element}] = int(r.pairs.size());
    EXPECT_TRUE(std::is_sorted(r.pairs.begin(), r.pairs.end()));
    for (int32_t i : r.pairs) {
      ASSERT_GE(i, 0);
      ASSERT_LT(i, int32_t(c.pairs.size()));
      EXPECT_EQ(c.pairs[i].out_element, r.out_element);
      EXPECT_EQ(c.pairs[i].in_element, r.in_element);
      ++seen[i];
    }
  }
  EXPECT_EQ(sizes, ref.relation_sizes);
  for (int s : seen) EXPECT_EQ(s, 1);
  for (size_t i = 1; i < c.relations.size(); ++i) {
    const ElementRelation &a = c.relations[i - 1], &b = c.relations[i];
    const bool ordered = a.pairs.size() > b.pairs.size() ||
                         (a.pairs.size() == b.pairs.size() &&
                          std::pair(a.out_element, a.in_element) < std::pair(b.out_element, b.in_element));
    EXPECT_TRUE(ordered) << "relations " << i - 1 << " and " << i;
  }
  for (size_t i = 1; i < c.pairs.size(); ++i)
    EXPECT_LT(std::pair(c.pairs[i - 1].out_element, c.pairs[i - 1].out_vertex),
              std::pair(c.pairs[i].out_element, c.pairs[i].out_vertex));
}

// ---- tests ----------------------------------------------------------------------------------

TEST(Correspondence, MatchesBruteForceOnRandomScene) {
  std::vector<TriMesh> ins, outs;
  for (int i = 0; i < 4; ++i) ins.push_back(sphere(5 + i % 2, 8, 1.0, Vec3(2.4 * i, 0.3 * i, 0), 10 + i));
  outs.push_back(sphere(6, 9, 0.9, Vec3(1.1, 0.4, 0.2), 20));
  outs.push_back(sphere(4, 7, 1.1, Vec3(3.9, -0.5, -0.1), 21));
  outs.push_back(sphere(5, 6, 1.0, Vec3(6.3, 1.2, 0.3), 22, /*flip=*/true));  // inward normals: rule (a)
  outs.push_back(sphere(4, 6, 0.5, Vec3(2.0, 4.0, 0.0), 23));                 // far from everything: rule (b)
  const auto in_overlap = [](const Vec3& p) { return p.x < 6.6; };
  int pruned_a = 0, pruned_b = 0;
  for (const CorrespondenceOptions& o : {CorrespondenceOptions{}, CorrespondenceOptions{1.0, 0.4},
                                         CorrespondenceOptions{0.0, 3.0}, CorrespondenceOptions{4.0, 1.0}}) {
    SCOPED_TRACE("lambda " + std::to_string(o.lambda) + " factor " + std::to_string(o.max_distance_factor));
    const Correspondences c = find_correspondences(outs, ins, in_overlap, o);
    EXPECT_FALSE(c.pairs.empty());
    Reference ref;
    expect_matches_reference(c, outs, ins, in_overlap, o, &ref);
    pruned_a += ref.pruned_a;
    pruned_b += ref.pruned_b;
  }
  // The scene exercises both per-pair rules.
  EXPECT_GT(pruned_a, 0);
  EXPECT_GT(pruned_b, 0);
}

// Inputs that are some of a swatch's elements moved by one translation, searched in the swatch's
// own index (SwatchFaces): the brute force's pairs, and bit for bit those of a search of the
// moved copies themselves.
TEST(Correspondence, ASwatchIndexGivesThePairsOfItsMovedElements) {
  std::vector<TriMesh> elements, outs;
  for (int i = 0; i < 6; ++i) elements.push_back(sphere(5 + i % 2, 8, 1.0, Vec3(2.4 * i, 0.3 * i, 0), 30 + i));
  const SwatchFaces faces(elements);
  const glm::dvec2 t(0.37, -1.21);
  const std::vector<int32_t> sources = {0, 2, 3, 5};
  std::vector<TriMesh> ins;
  for (int32_t k : sources) {
    TriMesh moved = elements[k];
    for (Vec3& p : moved.positions) p += Vec3(t, 0.0);
    ins.push_back(moved);
  }
  outs.push_back(sphere(6, 9, 0.9, Vec3(1.1, -0.8, 0.2), 40));
  outs.push_back(sphere(4, 7, 1.1, Vec3(5.2, -0.5, -0.1), 41));
  outs.push_back(sphere(5, 6, 1.0, Vec3(7.5, 0.1, 0.3), 42, /*flip=*/true));
  outs.push_back(sphere(5, 6, 1.0, Vec3(12.3, 0.4, 0.1), 43));
  outs.push_back(sphere(4, 6, 0.8, Vec3(9.8, 0.0, 0.0), 44));  // over element 4, not an input
  const auto in_overlap = [](const Vec3& p) { return p.x < 12.6; };
  for (const CorrespondenceOptions& o : {CorrespondenceOptions{}, CorrespondenceOptions{1.0, 0.4},
                                         CorrespondenceOptions{0.0, 3.0}, CorrespondenceOptions{4.0, 1.0}}) {
    SCOPED_TRACE("lambda " + std::to_string(o.lambda) + " factor " + std::to_string(o.max_distance_factor));
    const Correspondences indexed = find_correspondences(outs, ins, faces, sources, t, in_overlap, o);
    const Correspondences direct = find_correspondences(outs, ins, in_overlap, o);
    EXPECT_FALSE(indexed.pairs.empty());
    expect_matches_reference(indexed, outs, ins, in_overlap, o, nullptr);
    ASSERT_EQ(indexed.pairs.size(), direct.pairs.size());
    for (size_t k = 0; k < direct.pairs.size(); ++k) {
      const VertexFacePair &a = indexed.pairs[k], &b = direct.pairs[k];
      EXPECT_EQ(std::tie(a.out_element, a.out_vertex, a.in_element, a.in_face),
                std::tie(b.out_element, b.out_vertex, b.in_element, b.in_face)) << "pair " << k;
      EXPECT_EQ(a.closest, b.closest) << "pair " << k;
      EXPECT_EQ(a.barycentric, b.barycentric) << "pair " << k;
      EXPECT_EQ(a.distance, b.distance) << "pair " << k;
    }
    ASSERT_EQ(indexed.relations.size(), direct.relations.size());
    for (size_t r = 0; r < direct.relations.size(); ++r) {
      EXPECT_EQ(indexed.relations[r].out_element, direct.relations[r].out_element);
      EXPECT_EQ(indexed.relations[r].in_element, direct.relations[r].in_element);
      EXPECT_EQ(indexed.relations[r].pairs, direct.relations[r].pairs);
    }
  }
  EXPECT_THROW(find_correspondences(outs, ins, faces, {0, 2}, t, in_overlap), std::invalid_argument);
}

TEST(Correspondence, OppositeNormalsArePruned) {
  // An output plane facing down, just above an input plane facing up: every nearest face is
  // right below with the opposite normal.
  const std::vector<TriMesh> ins = {plane(3, 0.0)};
  const std::vector<TriMesh> outs = {plane(2, 0.1, /*down=*/true, Vec3(0.5, 0.5, 0))};
  const Correspondences c = find_correspondences(outs, ins, [](const Vec3&) { return true; });
  EXPECT_TRUE(c.pairs.empty());
  EXPECT_TRUE(c.relations.empty());
  // Facing up instead, every output vertex pairs with a face right below it.
  const std::vector<TriMesh> up = {plane(2, 0.1, false, Vec3(0.5, 0.5, 0))};
  const Correspondences d = find_correspondences(up, ins, [](const Vec3&) { return true; });
  EXPECT_EQ(d.pairs.size(), up[0].positions.size());
  for (const VertexFacePair& p : d.pairs) EXPECT_NEAR(p.distance, 0.1, 1e-12);
  ASSERT_EQ(d.relations.size(), 1u);
  EXPECT_EQ(d.relations[0].pairs.size(), up[0].positions.size());
}

TEST(Correspondence, DistantVerticesArePruned) {
  // Input: unit grid, so every face's local mean edge length is computable by hand for the
  // centre faces: a triangle (a, b, d) of the grid at the centre of a 4 x 4 grid.
  const std::vector<TriMesh> ins = {plane(4, 0.0)};
  // A tilted output strip whose vertices rise from 0.5 to 6 above the centre of the grid.
  TriMesh strip;
  for (int k = 0; k <= 11; ++k) {
    const double z = 0.5 + 0.5 * k;
    strip.positions.emplace_back(1.9, 2.0, z);
    strip.positions.emplace_back(2.1, 2.05, z);
  }
  for (int k = 0; k < 11; ++k) {
    strip.triangles.push_back({2 * k, 2 * k + 1, 2 * k + 3});
    strip.triangles.push_back({2 * k, 2 * k + 3, 2 * k + 2});
  }
  const auto all = [](const Vec3&) { return true; };
  for (double factor : {1.0, 3.0}) {
    const CorrespondenceOptions o{0.5, factor};
    const Correspondences c = find_correspondences({strip}, ins, all, o);
    expect_matches_reference(c, {strip}, ins, all, o);
    // The strip is vertical, so its normals are horizontal: dot with +z is 0, not pruned by (a).
    for (const VertexFacePair& p : c.pairs) {
      const double limit = factor * mean_edge_length_near(ins[0], p.in_face);
      EXPECT_LE(p.distance, limit);
    }
    // Some vertices were farther than the limit (mean edge length here is about 1.1).
    EXPECT_LT(c.pairs.size(), strip.positions.size());
    EXPECT_GT(c.pairs.size(), 0u);
  }
}

TEST(Correspondence, NonOverlappingProjectionsDropRelation) {
  // Input element: a steep wall-like tent over x in [0, 0.1]; output element: the same shape
  // shifted to x in [0.3, 0.4]. Vertices pair up (near, same normals) but the projections are
  // disjoint. A second output element sits right over the wall's foot and does overlap.
  TriMesh wall;
  wall.positions = {{0, 0, 0}, {0, 2, 0}, {0.1, 0, 1}, {0.1, 2, 1}};
  wall.triangles = {{0, 1, 3}, {0, 3, 2}};
  // Shifted copies keep the wall's normals, so rule (a) keeps their pairs.
  TriMesh beside = wall;
  for (Vec3& p : beside.positions) p.x -= 0.3;
  TriMesh over = wall;
  for (Vec3& p : over.positions) p += Vec3(-0.05, 0.5, 0.02);
  const std::vector<TriMesh> ins = {wall};
  const std::vector<TriMesh> outs = {beside, over};
  const auto all = [](const Vec3&) { return true; };
  const CorrespondenceOptions o{1.0, 10.0};
  const Correspondences c = find_correspondences(outs, ins, all, o);
  expect_matches_reference(c, outs, ins, all, o);
  ASSERT_EQ(c.relations.size(), 1u);
  EXPECT_EQ(c.relations[0].out_element, 1);
  for (const VertexFacePair& p : c.pairs) EXPECT_EQ(p.out_element, 1);
  // Without the second element, nothing is left although all four vertices of `beside` pair up
  // before rule (c).
  const Correspondences alone = find_correspondences({beside}, ins, all, o);
  EXPECT_TRUE(alone.pairs.empty());
  EXPECT_TRUE(alone.relations.empty());
  EXPECT_FALSE(projections_overlap(beside, wall));
  EXPECT_TRUE(projections_overlap(over, wall));
}

TEST(Correspondence, OnlyVerticesInOverlapAreQueried) {
  const std::vector<TriMesh> ins = {plane(4, 0.0)};
  const std::vector<TriMesh> outs = {plane(4, 0.2)};
  int calls = 0;
  const auto left = [&](const Vec3& p) {
    ++calls;
    return p.x < 1.5;
  };
  const Correspondences c = find_correspondences(outs, ins, left);
  EXPECT_EQ(calls, 25);
  EXPECT_EQ(c.pairs.size(), 10u);  // x = 0 and x = 1 columns
  for (const VertexFacePair& p : c.pairs) EXPECT_LT(outs[0].positions[p.out_vertex].x, 1.5);
}

TEST(Correspondence, RelationsSortedByPairCountThenIndices) {
  // Several output planes over several input planes with different overlaps.
  std::vector<TriMesh> ins, outs;
  for (int i = 0; i < 3; ++i) ins.push_back(plane(3, 0.0, false, Vec3(4.0 * i, 0, 0)));
  outs.push_back(plane(2, 0.1, false, Vec3(0.5, 0.5, 0)));   // 9 vertices over in 0
  outs.push_back(plane(1, 0.1, false, Vec3(4.5, 0.5, 0)));   // 4 over in 1
  outs.push_back(plane(1, 0.1, false, Vec3(8.5, 0.5, 0)));   // 4 over in 2
  outs.push_back(plane(3, 0.1, false, Vec3(2.5, 1.0, 0)));   // straddles in 0 and in 1
  const auto all = [](const Vec3&) { return true; };
  const Correspondences c = find_correspondences(outs, ins, all);
  expect_matches_reference(c, outs, ins, all, {});
  ASSERT_GE(c.relations.size(), 5u);
  EXPECT_EQ(c.relations[0].out_element, 0);
  EXPECT_EQ(c.relations[0].pairs.size(), 9u);
}

TEST(ProjectedOverlap, TrianglesMatchSeparatingAxes) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int overlapping = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Vec3 a[3], b[3];
    for (int k = 0; k < 3; ++k) a[k] = Vec3(u(rng), u(rng), u(rng)), b[k] = Vec3(u(rng) + 0.8, u(rng), u(rng));
    const bool expected = sat_overlap(a, b);
    overlapping += expected;
    ASSERT_EQ(projected_triangles_overlap(a[0], a[1], a[2], b[0], b[1], b[2]), expected) << trial;
  }
  EXPECT_GT(overlapping, 2000);
  EXPECT_LT(overlapping, 18000);
}

TEST(ProjectedOverlap, ConstructedAndDegenerateCases) {
  const Vec3 o(0, 0, 0), x(1, 0, 5), y(0, 1, -3);
  // Touching at a vertex and along an edge: closed sets overlap.
  EXPECT_TRUE(projected_triangles_overlap(o, x, y, x, Vec3(2, 0, 0), Vec3(2, 1, 0)));
  EXPECT_TRUE(projected_triangles_overlap(o, x, y, x, y, Vec3(1, 1, 0)));
  // One inside the other, boundaries disjoint.
  EXPECT_TRUE(projected_triangles_overlap(Vec3(-5, -5, 0), Vec3(5, -5, 0), Vec3(0, 5, 0), Vec3(0.1, 0.1, 0),
                                          Vec3(0.2, 0.1, 0), Vec3(0.1, 0.2, 9)));
  // Just apart.
  EXPECT_FALSE(projected_triangles_overlap(o, x, y, Vec3(0.6, 0.6, 0), Vec3(2, 0.6, 0), Vec3(0.6, 2, 0)));
  // A vertical triangle projects to a segment: crossing a triangle, or not.
  const Vec3 s0(-1, 0.25, 0), s1(2, 0.25, 0), s2(2, 0.25, 1);
  EXPECT_TRUE(projected_triangles_overlap(s0, s1, s2, o, x, y));
  EXPECT_FALSE(projected_triangles_overlap(Vec3(-1, 2, 0), Vec3(2, 2, 0), Vec3(2, 2, 1), o, x, y));
  // Two collinear segments on one line, disjoint (a plain separating-axis test gets this wrong)
  // and overlapping.
  EXPECT_FALSE(projected_triangles_overlap(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(2, 0, 0),
                                           Vec3(3, 0, 0), Vec3(3, 0, 1)));
  EXPECT_TRUE(projected_triangles_overlap(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 1), Vec3(1, 0, 0),
                                          Vec3(3, 0, 0), Vec3(3, 0, 1)));
  // A triangle seen edge-on, projected to a point, inside a triangle.
  EXPECT_TRUE(projected_triangles_overlap(Vec3(0.2, 0.2, 0), Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 2), o, x, y));
  EXPECT_FALSE(projected_triangles_overlap(Vec3(0.8, 0.8, 0), Vec3(0.8, 0.8, 1), Vec3(0.8, 0.8, 2), o, x, y));
}

TEST(ProjectedOverlap, MeshesMatchAllPairs) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  auto soup = [&](int n, double cx, double size) {
    TriMesh m;
    for (int f = 0; f < n; ++f) {
      const Vec3 c(cx + 3 * u(rng), 3 * u(rng), u(rng));
      for (int k = 0; k < 3; ++k) m.positions.push_back(c + size * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng)));
      m.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
    }
    return m;
  };
  int positive = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const TriMesh a = soup(1 + trial % 40, 0.0, 0.3), b = soup(1 + trial % 23, 1.0 + 2.0 * u(rng), 0.3);
    const bool expected = brute_projections_overlap(a, b);
    positive += expected;
    ASSERT_EQ(projections_overlap(a, b), expected) << trial;
  }
  EXPECT_GT(positive, 40);
  EXPECT_LT(positive, 160);
}

TEST(Correspondence, RealMeshMatchesBruteForce) {
  const std::filesystem::path file = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes/knot.off";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const TriMesh knot = read_mesh(file);
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : knot.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double diag = glm::length(hi - lo);
  // The output: the knot moved a little, so most vertices pair with a face near their own, and
  // an overlap band across the knot keeps the brute force small.
  TriMesh moved = knot;
  for (Vec3& p : moved.positions) p += diag * Vec3(0.004, -0.003, 0.002);
  const double x0 = lo.x + 0.45 * (hi.x - lo.x), x1 = lo.x + 0.52 * (hi.x - lo.x);
  const auto band = [&](const Vec3& p) { return p.x > x0 && p.x < x1; };
  const std::vector<TriMesh> ins = {knot}, outs = {moved};
  const CorrespondenceOptions o{20.0 / diag, 3.0};  // distance weighed at the scale of the mesh
  const Correspondences c = find_correspondences(outs, ins, band, o);
  EXPECT_GT(c.pairs.size(), 100u);
  expect_matches_reference(c, outs, ins, band, o);
}

TEST(Correspondence, RejectsBadOptions) {
  const std::vector<TriMesh> ins = {plane(1, 0.0)}, outs = {plane(1, 0.1)};
  const auto all = [](const Vec3&) { return true; };
  EXPECT_THROW(find_correspondences(outs, ins, all, {-1.0, 3.0}), InputError);
  EXPECT_THROW(find_correspondences(outs, ins, all, {1.0, 0.0}), InputError);
  TriMesh bad = plane(1, 0.0);
  bad.triangles[0][1] = 42;
  EXPECT_THROW(find_correspondences(outs, {bad}, all), InputError);
  EXPECT_TRUE(find_correspondences({}, ins, all).pairs.empty());
  EXPECT_TRUE(find_correspondences(outs, {}, all).pairs.empty());
}

}  // namespace
}  // namespace meshquilt
