// Exact predicates against integer arithmetic; the triangle-triangle test against an independent
// separating-axis test; intersecting_face_pairs against an O(n^2) edge-against-triangle search.
#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <random>
#include <vector>

#include "mesh/mesh_io.h"
#include "mesh/topology.h"
#include "spatial/exact_predicates.h"
#include "spatial/intersecting_pairs.h"
#include "spatial/triangle_intersection.h"

namespace meshquilt {
namespace {

using i128 = __int128;

int sign128(i128 x) { return (x > 0) - (x < 0); }

// orient3d on integer-valued doubles, exactly, in 128-bit integers.
int orient3d_int(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  auto I = [](double x) { return static_cast<i128>(static_cast<long long>(x)); };
  const i128 bx = I(b.x) - I(a.x), by = I(b.y) - I(a.y), bz = I(b.z) - I(a.z);
  const i128 cx = I(c.x) - I(a.x), cy = I(c.y) - I(a.y), cz = I(c.z) - I(a.z);
  const i128 dx = I(d.x) - I(a.x), dy = I(d.y) - I(a.y), dz = I(d.z) - I(a.z);
  return sign128((by * cz - bz * cy) * dx + (bz * cx - bx * cz) * dy + (bx * cy - by * cx) * dz);
}

TEST(ExactPredicates, Orient3dMatchesIntegerArithmeticNearDegenerate) {
  // Large offsets with small differences: rounding in the naive formula, exactness required.
  std::mt19937_64 rng(1);
  const double offset = std::ldexp(1.0, 40);
  std::uniform_int_distribution<long long> small(-1000, 1000);
  int zeros = 0;
  for (int i = 0; i < 200000; ++i) {
    auto pt = [&] { return Vec3(offset + small(rng), offset - small(rng), offset + 3 * small(rng)); };
    const Vec3 a = pt(), b = pt(), c = pt();
    // d on or near the plane through a, b, c: a + s (b - a) + t (c - a) + small jitter.
    const long long s = small(rng) % 3, t = small(rng) % 3;
    Vec3 d = a + double(s) * (b - a) + double(t) * (c - a);
    if (i % 2) d.x += double(small(rng) % 2);
    const int expected = orient3d_int(a, b, c, d);
    zeros += expected == 0;
    ASSERT_EQ(orient3d(a, b, c, d), expected) << i;
  }
  EXPECT_GT(zeros, 50000);
}

// Reference exact orient3d with heap expansions summed by Grow-Expansion (quadratic, simple):
// a different summation from the library's merge-based one.
namespace slow {
using E = std::vector<double>;
void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a, av = x - bv;
  y = (a - av) + (b - bv);
}
E grow(const E& e, double b) {
  E h;
  double q = b;
  for (double x : e) {
    double s, t;
    two_sum(q, x, s, t);
    h.push_back(t);
    q = s;
  }
  h.push_back(q);
  return h;
}
E sum(E e, const E& f) {
  for (double x : f) e = grow(e, x);
  return e;
}
E scale(const E& e, double b) {
  E h{0.0};
  for (double x : e) {
    const double p = x * b;
    h = grow(grow(h, std::fma(x, b, -p)), p);
  }
  return h;
}
E mul(const E& e, const E& f) {
  E h{0.0};
  for (double x : f) h = sum(h, scale(e, x));
  return h;
}
E diff(double a, double b) {
  double x, y;
  two_sum(a, -b, x, y);
  return {y, x};
}
int sign(const E& e) {
  // Components are non-overlapping but may include zeros anywhere: the largest magnitude wins.
  double top = 0.0;
  for (double x : e)
    if (std::abs(x) > std::abs(top)) top = x;
  return (top > 0) - (top < 0);
}
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const E bx = diff(b.x, a.x), by = diff(b.y, a.y), bz = diff(b.z, a.z);
  const E cx = diff(c.x, a.x), cy = diff(c.y, a.y), cz = diff(c.z, a.z);
  const E dx = diff(d.x, a.x), dy = diff(d.y, a.y), dz = diff(d.z, a.z);
  auto neg = [](E e) {
    for (double& x : e) x = -x;
    return e;
  };
  const E nx = sum(mul(by, cz), neg(mul(bz, cy)));
  const E ny = sum(mul(bz, cx), neg(mul(bx, cz)));
  const E nz = sum(mul(bx, cy), neg(mul(by, cx)));
  return sign(sum(sum(mul(nx, dx), mul(ny, dy)), mul(nz, dz)));
}
}  // namespace slow

TEST(ExactPredicates, Orient3dMatchesReferenceWithInexactDifferences) {
  // Mixed magnitudes make the coordinate differences inexact in double; d is constructed on
  // the plane in floating point, so it lies within rounding of it: the hard cases.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-30, 30);
  int nonzero = 0;
  for (int i = 0; i < 1500; ++i) {
    auto pt = [&] { return Vec3(std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), e(rng))); };
    const Vec3 a = pt(), b = pt(), c = pt();
    const double s = u(rng), t = u(rng);
    const Vec3 d = a + s * (b - a) + t * (c - a);
    const int expected = slow::orient3d(a, b, c, d);
    nonzero += expected != 0;
    ASSERT_EQ(orient3d(a, b, c, d), expected) << i;
    ASSERT_EQ(orient3d(b, c, a, d), expected) << i;  // cyclic permutations agree
    ASSERT_EQ(orient3d(a, c, b, d), -expected) << i;
  }
  EXPECT_GT(nonzero, 100);
}

TEST(ExactPredicates, Orient2dOnUlpGrid) {
  // Shewchuk's example: points on a grid of ulps around (0.5, 0.5) against the line through
  // (12, 12) and (24, 24); scaled by 2^53 every coordinate is an integer.
  const double ulp = std::ldexp(1.0, -53);
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const double px = 0.5 + i * ulp, py = 0.5 + j * ulp;
      const i128 sx = static_cast<i128>(std::ldexp(1.0, 52)) + i, sy = static_cast<i128>(std::ldexp(1.0, 52)) + j;
      const i128 ax = static_cast<i128>(12) << 53, bx = static_cast<i128>(24) << 53;
      const i128 det = (bx - ax) * (sy - ax) - (bx - ax) * (sx - ax);
      ASSERT_EQ(orient2d(12, 12, 24, 24, px, py), sign128(det)) << i << " " << j;
    }
  }
}

// Independent triangle-triangle test: separating axes on integer coordinates (exact in 64-bit).
// Two convex sets are disjoint iff some axis separates them strictly; for two triangles the
// candidates are both normals, the nine edge-edge cross products and the in-plane edge normals.
struct IV {
  long long x, y, z;
};
IV sub(IV a, IV b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
IV cross(IV a, IV b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
long long dot(IV a, IV b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

bool sat_intersect(const std::array<IV, 3>& t1, const std::array<IV, 3>& t2) {
  std::vector<IV> axes;
  const IV n1 = cross(sub(t1[1], t1[0]), sub(t1[2], t1[0]));
  const IV n2 = cross(sub(t2[1], t2[0]), sub(t2[2], t2[0]));
  axes.push_back(n1);
  axes.push_back(n2);
  for (int i = 0; i < 3; ++i) {
    const IV e1 = sub(t1[(i + 1) % 3], t1[i]);
    const IV e2 = sub(t2[(i + 1) % 3], t2[i]);
    axes.push_back(cross(n1, e1));
    axes.push_back(cross(n2, e2));
    for (int j = 0; j < 3; ++j) axes.push_back(cross(e1, sub(t2[(j + 1) % 3], t2[j])));
  }
  for (const IV& axis : axes) {
    if (axis.x == 0 && axis.y == 0 && axis.z == 0) continue;
    long long lo1 = dot(axis, t1[0]), hi1 = lo1, lo2 = dot(axis, t2[0]), hi2 = lo2;
    for (int i = 1; i < 3; ++i) {
      lo1 = std::min(lo1, dot(axis, t1[i]));
      hi1 = std::max(hi1, dot(axis, t1[i]));
      lo2 = std::min(lo2, dot(axis, t2[i]));
      hi2 = std::max(hi2, dot(axis, t2[i]));
    }
    if (hi1 < lo2 || hi2 < lo1) return false;
  }
  return true;
}

Vec3 to_vec(IV v) { return Vec3(double(v.x), double(v.y), double(v.z)); }

TEST(TrianglesIntersect, AgreesWithSeparatingAxesOnIntegerGrid) {
  // A 4x4x4 grid makes coplanar, touching, edge-sharing and vertex-sharing pairs common.
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> g(0, 3);
  int hits = 0, coplanar = 0, tested = 0;
  for (int i = 0; i < 300000; ++i) {
    std::array<IV, 3> t1, t2;
    for (auto& v : t1) v = {g(rng), g(rng), g(rng)};
    for (auto& v : t2) v = {g(rng), g(rng), g(rng)};
    const IV n1 = cross(sub(t1[1], t1[0]), sub(t1[2], t1[0]));
    const IV n2 = cross(sub(t2[1], t2[0]), sub(t2[2], t2[0]));
    if ((n1.x == 0 && n1.y == 0 && n1.z == 0) || (n2.x == 0 && n2.y == 0 && n2.z == 0)) continue;
    ++tested;
    const bool expected = sat_intersect(t1, t2);
    hits += expected;
    coplanar += dot(n1, sub(t2[0], t1[0])) == 0 && dot(n1, sub(t2[1], t1[0])) == 0 && dot(n1, sub(t2[2], t1[0])) == 0;
    const bool got = triangles_intersect(to_vec(t1[0]), to_vec(t1[1]), to_vec(t1[2]), to_vec(t2[0]), to_vec(t2[1]), to_vec(t2[2]));
    ASSERT_EQ(got, expected) << "case " << i;
    // Symmetric, and invariant under vertex order.
    ASSERT_EQ(triangles_intersect(to_vec(t2[1]), to_vec(t2[0]), to_vec(t2[2]), to_vec(t1[2]), to_vec(t1[0]), to_vec(t1[1])), expected);
  }
  EXPECT_GT(hits, tested / 10);
  EXPECT_LT(hits, tested - tested / 10);
  EXPECT_GT(coplanar, 500);
}

TEST(TrianglesIntersect, ExactConstructedCases) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Sharing an edge or a vertex: touching, so intersecting.
  EXPECT_TRUE(triangles_intersect(a, b, c, a, b, Vec3(0, -1, 0.5)));
  EXPECT_TRUE(triangles_intersect(a, b, c, a, Vec3(-1, 0, 1), Vec3(0, -1, 1)));
  // Piercing, and a near miss by one ulp above the plane.
  EXPECT_TRUE(triangles_intersect(a, b, c, Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(3, 3, 0.5)));
  const double up = std::nextafter(0.0, 1.0);
  EXPECT_FALSE(triangles_intersect(a, b, c, Vec3(0.2, 0.2, up), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)));
  EXPECT_TRUE(triangles_intersect(a, b, c, Vec3(0.2, 0.2, 0.0), Vec3(0.3, 0.2, 1), Vec3(0.2, 0.3, 1)));
  // Coplanar: disjoint, overlapping, one inside the other.
  EXPECT_FALSE(triangles_intersect(a, b, c, Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)));
  EXPECT_TRUE(triangles_intersect(a, b, c, Vec3(0.5, 0.5, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)));
  EXPECT_TRUE(triangles_intersect(a, b, c, Vec3(0.1, 0.1, 0), Vec3(0.2, 0.1, 0), Vec3(0.1, 0.2, 0)));
  // Degenerate triangle (a segment) through the face, and beside it.
  EXPECT_TRUE(triangles_intersect(a, b, c, Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 0.5)));
  EXPECT_FALSE(triangles_intersect(a, b, c, Vec3(2, 2, -1), Vec3(2, 2, 1), Vec3(2, 2, 0.5)));
  EXPECT_TRUE(segments_intersect(a, b, Vec3(0.5, -1, 0), Vec3(0.5, 1, 0)));
  EXPECT_FALSE(segments_intersect(a, b, Vec3(0.5, -1, 1e-300), Vec3(0.5, 1, 1e-300)));
}

// Reference for meshes: closed triangles meet iff an edge of one meets the other (the boundary
// of their convex intersection lies on their edges). Segment against triangle by orientations.
bool ref_segment_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r) {
  const int sa = orient3d(p, q, r, a), sb = orient3d(p, q, r, b);
  if (sa * sb > 0) return false;
  if (sa == 0 && sb == 0) {
    // Coplanar: in the projection along the largest normal component.
    const Vec3 n = glm::abs(glm::cross(q - p, r - p));
    const int k = n.x >= n.y && n.x >= n.z ? 0 : (n.y >= n.z ? 1 : 2);
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    auto o = [&](const Vec3& u, const Vec3& v, const Vec3& w) { return orient2d(u[i], u[j], v[i], v[j], w[i], w[j]); };
    auto inside = [&](const Vec3& x) {
      const int s1 = o(p, q, x), s2 = o(q, r, x), s3 = o(r, p, x);
      return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
    };
    if (inside(a) || inside(b)) return true;
    const Vec3 tri[3] = {p, q, r};
    for (int e = 0; e < 3; ++e) {
      const Vec3 &c = tri[e], &d = tri[(e + 1) % 3];
      const int o1 = o(a, b, c), o2 = o(a, b, d), o3 = o(c, d, a), o4 = o(c, d, b);
      if (o1 * o2 < 0 && o3 * o4 < 0) return true;
      auto on = [&](const Vec3& u, const Vec3& v, const Vec3& x) {
        return std::min(u[i], v[i]) <= x[i] && x[i] <= std::max(u[i], v[i]) && std::min(u[j], v[j]) <= x[j] &&
               x[j] <= std::max(u[j], v[j]);
      };
      if ((o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) || (o4 == 0 && on(c, d, b)))
        return true;
    }
    return false;
  }
  const int s1 = orient3d(a, b, p, q), s2 = orient3d(a, b, q, r), s3 = orient3d(a, b, r, p);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool ref_triangles(const TriMesh& m, int f, int g) {
  const auto& x = m.positions;
  const Tri &a = m.triangles[f], &b = m.triangles[g];
  for (int e = 0; e < 3; ++e) {
    if (ref_segment_triangle(x[a[e]], x[a[(e + 1) % 3]], x[b[0]], x[b[1]], x[b[2]])) return true;
    if (ref_segment_triangle(x[b[e]], x[b[(e + 1) % 3]], x[a[0]], x[a[1]], x[a[2]])) return true;
  }
  return false;
}

bool boxes_touch(const TriMesh& m, int f, int g) {
  for (int k = 0; k < 3; ++k) {
    double lo1 = 1e300, hi1 = -1e300, lo2 = 1e300, hi2 = -1e300;
    for (int32_t v : m.triangles[f]) {
      lo1 = std::min(lo1, m.positions[v][k]);
      hi1 = std::max(hi1, m.positions[v][k]);
    }
    for (int32_t v : m.triangles[g]) {
      lo2 = std::min(lo2, m.positions[v][k]);
      hi2 = std::max(hi2, m.positions[v][k]);
    }
    if (hi1 < lo2 || hi2 < lo1) return false;
  }
  return true;
}

void expect_matches_brute_force(const TriMesh& m, const std::vector<int32_t>& element, size_t min_different, size_t min_same) {
  std::vector<FacePair> different, same;
  const int n = static_cast<int>(m.num_faces());
  for (int f = 0; f < n; ++f) {
    for (int g = f + 1; g < n; ++g) {
      const Tri &a = m.triangles[f], &b = m.triangles[g];
      bool adjacent = false;
      for (int32_t u : a) adjacent |= (u == b[0] || u == b[1] || u == b[2]);
      if (element[f] == element[g] && adjacent) continue;
      // Disjoint bounding boxes cannot meet (keeps the O(n^2) search fast; the exact part below
      // decides every other pair).
      if (!boxes_touch(m, f, g)) continue;
      if (ref_triangles(m, f, g)) (element[f] == element[g] ? same : different).emplace_back(f, g);
    }
  }
  const FaceIntersections found = find_intersecting_faces(m, element);
  EXPECT_GE(different.size(), min_different);
  EXPECT_GE(same.size(), min_same);
  EXPECT_EQ(found.different_elements, different);
  EXPECT_EQ(found.same_element, same);
  EXPECT_EQ(intersecting_face_pairs(m, element, IntersectionScope::different_elements), different);
  EXPECT_EQ(intersecting_face_pairs(m, element, IntersectionScope::same_element), same);
}

// Two copies of a mesh, the second rotated and shifted: as two elements (pairs between them)
// and as one element (the same pairs become self-intersections).
TriMesh with_moved_copy(const TriMesh& m, double shift) {
  TriMesh out = m;
  const int32_t nv = static_cast<int32_t>(m.num_vertices());
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (const Vec3& v : m.positions) out.positions.emplace_back(c * v.x - s * v.y + shift, s * v.x + c * v.y, v.z + 0.3 * shift);
  for (const Tri& t : m.triangles) out.triangles.push_back({t[0] + nv, t[1] + nv, t[2] + nv});
  out.elements.assign(m.num_faces(), 0);
  out.elements.resize(out.num_faces(), 1);
  return out;
}

class RealMeshPairs : public ::testing::TestWithParam<const char*> {};

TEST_P(RealMeshPairs, MatchBruteForce) {
  const auto file = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data" / "meshes" / GetParam();
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "shared meshes not available";
  TriMesh m = weld_vertices(read_mesh(file));
  // Keep the pair search small: the first faces of the mesh (a connected-ish patch).
  if (m.num_faces() > 900) m.triangles.resize(900);
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& v : m.positions) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const TriMesh two = with_moved_copy(m, 0.1 * glm::length(hi - lo));
  expect_matches_brute_force(two, two.elements, 1, 0);
  expect_matches_brute_force(two, std::vector<int32_t>(two.num_faces(), 0), 0, 1);
}

// Tested again after some elements moved, only their pairs are looked at; the answer is that of
// testing every face at the new places.
TEST(IntersectingFaces, AgainAfterElementsMoveAsIfTestedAfresh) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> at(0.0, 8.0), size(0.5, 2.0), shift(-1.0, 1.0);
  TriMesh m;
  std::vector<int32_t> element;
  for (int e = 0; e < 300; ++e) {
    const Vec3 o(at(rng), at(rng), at(rng));
    const int32_t first = static_cast<int32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {o, o + Vec3(size(rng), 0, 0), o + Vec3(0, size(rng), 0), o + Vec3(0, 0, size(rng))});
    for (const Tri& t : std::vector<Tri>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
      m.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
      element.push_back(e);
    }
  }
  FaceIntersections found = find_intersecting_faces(m, element);
  EXPECT_GT(found.different_elements.size(), 50u);
  for (int round = 0; round < 3; ++round) {
    std::vector<uint8_t> moved(300, 0);
    for (int k = 0; k < 40; ++k) {
      const int e = static_cast<int>(rng() % 300);
      moved[e] = 1;
    }
    for (int e = 0; e < 300; ++e) {
      if (!moved[e]) continue;
      const Vec3 d(shift(rng), shift(rng), shift(rng));
      for (int v = 0; v < 4; ++v) m.positions[4 * e + v] += d;
    }
    found = find_intersecting_faces_again(m, element, found, moved);
    const FaceIntersections fresh = find_intersecting_faces(m, element);
    EXPECT_EQ(found.different_elements, fresh.different_elements) << "round " << round;
    EXPECT_EQ(found.same_element, fresh.same_element) << "round " << round;
  }
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, RealMeshPairs, ::testing::Values("sphere.off", "knot.off", "plane.off", "head.off"));

}  // namespace
}  // namespace meshquilt
