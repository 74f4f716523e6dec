// FaceBvh against brute force over every face: closest points, min-cost faces, box queries.
#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <random>
#include <thread>
#include <tuple>

#include "mesh/mesh_io.h"
#include "spatial/face_bvh.h"

namespace meshquilt {
namespace {

const std::filesystem::path kMeshes = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data" / "meshes";

TriMesh load_or_skip(const char* name) {
  const auto file = kMeshes / name;
  if (!std::filesystem::exists(file)) return {};
  return read_mesh(file);
}

// Independent reference: distance to a triangle by minimizing over a projection onto the plane
// (when inside) and the three edges, written without Ericson's region tests.
double reference_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  double best = std::numeric_limits<double>::infinity();
  if (n2 > 0.0) {
    const Vec3 q = p - glm::dot(p - a, n) / n2 * n;
    const double w0 = glm::dot(glm::cross(b - q, c - q), n);
    const double w1 = glm::dot(glm::cross(c - q, a - q), n);
    const double w2 = glm::dot(glm::cross(a - q, b - q), n);
    if (w0 >= 0 && w1 >= 0 && w2 >= 0) best = glm::length(p - q);
  }
  const Vec3 v[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = v[(i + 1) % 3] - v[i];
    const double t = std::clamp(glm::dot(p - v[i], e) / std::max(glm::dot(e, e), 1e-300), 0.0, 1.0);
    best = std::min(best, glm::length(p - (v[i] + t * e)));
  }
  return best;
}

struct Bounds {
  Vec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
};
Bounds bounds_of(const TriMesh& m) {
  Bounds b;
  for (const Vec3& v : m.positions) {
    b.lo = glm::min(b.lo, v);
    b.hi = glm::max(b.hi, v);
  }
  return b;
}

TEST(ClosestPointOnTriangle, MatchesReferenceOnRandomTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vec3 p(2 * u(rng), 2 * u(rng), 2 * u(rng));
    const ClosestPoint cp = closest_point_on_triangle(p, a, b, c);
    EXPECT_NEAR(cp.distance, reference_distance(p, a, b, c), 1e-12);
    const Vec3 from_bary = cp.barycentric.x * a + cp.barycentric.y * b + cp.barycentric.z * c;
    EXPECT_NEAR(glm::length(from_bary - cp.point), 0.0, 1e-12);
    EXPECT_NEAR(cp.barycentric.x + cp.barycentric.y + cp.barycentric.z, 1.0, 1e-12);
  }
}

TEST(ClosestPointOnTriangle, ExactCases) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_DOUBLE_EQ(closest_point_on_triangle({0.25, 0.25, 2.0}, a, b, c).distance, 2.0);
  EXPECT_DOUBLE_EQ(closest_point_on_triangle({-3.0, -4.0, 0.0}, a, b, c).distance, 5.0);
  const ClosestPoint edge = closest_point_on_triangle({0.5, -1.0, 0.0}, a, b, c);
  EXPECT_DOUBLE_EQ(edge.distance, 1.0);
  EXPECT_DOUBLE_EQ(edge.barycentric.y, 0.5);
}

// A repeated vertex leaves an edge of zero length: the distance is still that to the segment.
TEST(ClosestPointOnTriangle, RepeatedVertexGivesTheSegmentDistance) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vec3 p(2 * u(rng), 2 * u(rng), 2 * u(rng));
    for (const auto& [x, y, z] : {std::tuple{a, a, c}, std::tuple{a, c, c}, std::tuple{c, a, c}, std::tuple{a, a, a}}) {
      const ClosestPoint cp = closest_point_on_triangle(p, x, y, z);
      ASSERT_TRUE(std::isfinite(cp.distance));
      EXPECT_NEAR(cp.distance, reference_distance(p, x, y, z), 1e-12);
    }
  }
}

class RealMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(RealMesh, ClosestPointAndMinCostMatchBruteForce) {
  const TriMesh mesh = load_or_skip(GetParam());
  if (mesh.num_faces() == 0) GTEST_SKIP() << "shared meshes not available";
  const FaceBvh bvh(mesh);
  const Bounds b = bounds_of(mesh);
  const Vec3 size = b.hi - b.lo;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  // Face normals for an Eq. 1-like cost: distance plus a normal-mismatch term.
  std::vector<Vec3> normals(mesh.num_faces());
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    normals[f] = glm::length(n) > 0 ? glm::normalize(n) : Vec3(0, 0, 1);
  }
  const double lambda = 1.0 / glm::length(size);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = b.lo + Vec3(u(rng), u(rng), u(rng)) * size;
    const Vec3 n = glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    double brute_d = std::numeric_limits<double>::infinity();
    double brute_cost = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      const Tri& t = mesh.triangles[f];
      const double d = reference_distance(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
      brute_d = std::min(brute_d, d);
      brute_cost = std::min(brute_cost, 1.0 + lambda * d + (1.0 - glm::dot(n, normals[f])));
    }
    const ClosestPoint cp = bvh.closest_point(p);
    ASSERT_GE(cp.face, 0);
    EXPECT_NEAR(cp.distance, brute_d, 1e-12 * glm::length(size));
    // With a radius below the true distance nothing is found.
    EXPECT_EQ(bvh.closest_point(p, 0.5 * brute_d).face, -1);

    double best = 0.0;
    const ClosestPoint mc = bvh.min_cost_face(
        p, [&](const ClosestPoint& c) { return 1.0 + lambda * c.distance + (1.0 - glm::dot(n, normals[c.face])); },
        [&](double cost) { return (cost - 1.0) / lambda; }, &best);
    ASSERT_GE(mc.face, 0);
    EXPECT_NEAR(best, brute_cost, 1e-12);

    // A lower bound per face (its bounding sphere's gap for the distance) passes over faces
    // and changes nothing; a bound that rules out the best face is obeyed.
    const auto gap_bound = [&](int32_t f) {
      const Tri& t = mesh.triangles[f];
      const Vec3 centre = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
      double radius = 0.0;
      for (int32_t v : t) radius = std::max(radius, glm::length(mesh.positions[v] - centre));
      return 1.0 + lambda * std::max(glm::length(p - centre) - radius * (1.0 + 1e-9), 0.0) + (1.0 - glm::dot(n, normals[f]));
    };
    const auto cost_of = [&](const ClosestPoint& c) { return 1.0 + lambda * c.distance + (1.0 - glm::dot(n, normals[c.face])); };
    const auto radius_of = [&](double cost) { return (cost - 1.0) / lambda; };
    double bounded = 0.0;
    const ClosestPoint with_bound =
        bvh.min_cost_face(p, cost_of, radius_of, &bounded, std::numeric_limits<double>::infinity(), gap_bound);
    EXPECT_EQ(with_bound.face, mc.face);
    EXPECT_EQ(bounded, best);
    double without_best = 0.0;
    // (Once some cost is known: the bound is compared with the best so far.)
    const ClosestPoint other = bvh.min_cost_face(p, cost_of, radius_of, &without_best, 2.0 * best,
                                                 [&](int32_t f) { return f == mc.face ? INFINITY : gap_bound(f); });
    EXPECT_NE(other.face, mc.face);
    EXPECT_GE(without_best, best);
  }
}

TEST_P(RealMesh, FacesInBoxMatchBruteForce) {
  const TriMesh mesh = load_or_skip(GetParam());
  if (mesh.num_faces() == 0) GTEST_SKIP() << "shared meshes not available";
  const FaceBvh bvh(mesh);
  const Bounds b = bounds_of(mesh);
  const Vec3 size = b.hi - b.lo;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const Vec3 c = b.lo + Vec3(u(rng), u(rng), u(rng)) * size;
    const Vec3 half = Vec3(u(rng), u(rng), u(rng)) * size * 0.15;
    std::vector<int32_t> found;
    bvh.faces_in_box(c - half, c + half, found);
    std::sort(found.begin(), found.end());
    std::vector<int32_t> expected;
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
      for (int32_t v : mesh.triangles[f]) {
        lo = glm::min(lo, mesh.positions[v]);
        hi = glm::max(hi, mesh.positions[v]);
      }
      const Vec3 qlo = c - half, qhi = c + half;
      if (lo.x <= qhi.x && qlo.x <= hi.x && lo.y <= qhi.y && qlo.y <= hi.y && lo.z <= qhi.z && qlo.z <= hi.z) {
        expected.push_back(static_cast<int32_t>(f));
      }
    }
    EXPECT_EQ(found, expected);
  }
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, RealMesh, ::testing::Values("sphere.off", "cylinder.off", "head.off"));

TEST(FaceBvh, ExactFarFromTheOriginAndFromManyThreads) {
  // A small bumpy sheet 1e6 away from the origin: float rounding of coordinates (about 0.06)
  // is far larger than the features (0.01), so only the double tests can decide.
  TriMesh mesh;
  const int n = 40;
  const Vec3 offset(1e6, -2e6, 5e5);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.positions.push_back(offset + Vec3(0.01 * i, 0.01 * j, 0.003 * std::sin(i * 1.3 + j * 0.7)));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t a = j * (n + 1) + i;
      mesh.triangles.push_back({a, a + 1, a + n + 2});
      mesh.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  const FaceBvh bvh(mesh);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.05, 0.45);
  std::vector<Vec3> points;
  for (int i = 0; i < 300; ++i) points.push_back(offset + Vec3(u(rng), u(rng), 0.1 * u(rng)));
  std::vector<double> expected(points.size(), std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < points.size(); ++i)
    for (const Tri& t : mesh.triangles)
      expected[i] = std::min(expected[i], reference_distance(points[i], mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
  std::vector<double> got(points.size());
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      for (size_t i = k; i < points.size(); i += 4) got[i] = bvh.closest_point(points[i]).distance;
    });
  }
  for (auto& t : threads) t.join();
  for (size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-9) << i;
}

// Six coplanar faces around a vertex, a point straight above it: every face is as near and
// faces the same way, so every cost ties, and the lowest index wins, also against a known face.
TEST(FaceBvh, MinCostTiesGoToTheLowestIndex) {
  TriMesh fan;
  fan.positions.emplace_back(0.0, 0.0, 0.0);
  for (int k = 0; k < 6; ++k) fan.positions.emplace_back(std::cos(k * M_PI / 3.0), std::sin(k * M_PI / 3.0), 0.0);
  for (int k = 0; k < 6; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  // Listed in reverse, so that the lowest index is not the first face built.
  std::reverse(fan.triangles.begin(), fan.triangles.end());
  const FaceBvh bvh(fan);
  const Vec3 p(0.0, 0.0, 0.5);
  const auto cost = [](const ClosestPoint& c) { return 1.0 + c.distance; };
  const auto radius = [](double c) { return c - 1.0; };
  double best = 0.0;
  EXPECT_EQ(bvh.min_cost_face(p, cost, radius, &best).face, 0);
  EXPECT_EQ(best, 1.5);
  // Known to cost 1.5 at face 3: face 0 ties it with a lower index.
  EXPECT_EQ(bvh.min_cost_face(p, cost, radius, &best, 1.5, {}, 3).face, 0);
  // Known at face 0, or at some face: nothing beats it.
  EXPECT_EQ(bvh.min_cost_face(p, cost, radius, &best, 1.5, {}, 0).face, -1);
  EXPECT_EQ(bvh.min_cost_face(p, cost, radius, &best, 1.5).face, -1);
  EXPECT_EQ(best, 1.5);
}

TEST(FaceBvh, EmptyMeshFindsNothing) {
  const TriMesh empty;
  const FaceBvh bvh(empty);
  EXPECT_EQ(bvh.closest_point({0, 0, 0}).face, -1);
  std::vector<int32_t> faces;
  bvh.faces_in_box({-1, -1, -1}, {1, 1, 1}, faces);
  EXPECT_TRUE(faces.empty());
}

TEST(FaceBvh, OverlappingPairsMatchBruteForce) {
  // Random small triangles in a cube: every pair with overlapping boxes, exactly once.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 10.0), d(-0.6, 0.6);
  TriMesh mesh;
  for (int i = 0; i < 1500; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const int32_t base = static_cast<int32_t>(mesh.positions.size());
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + Vec3(d(rng), d(rng), d(rng)));
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  std::mutex m;
  std::vector<std::pair<int32_t, int32_t>> found;
  const FaceBvh bvh(mesh);
  bvh.for_each_overlapping_pair([&](int32_t f, int32_t g) {
    std::lock_guard<std::mutex> lock(m);
    found.emplace_back(f, g);
  });
  std::sort(found.begin(), found.end());
  std::vector<std::pair<int32_t, int32_t>> expected;
  auto box = [&](int f, Vec3& lo, Vec3& hi) {
    lo = Vec3(1e300);
    hi = Vec3(-1e300);
    for (int32_t v : mesh.triangles[f]) {
      lo = glm::min(lo, mesh.positions[v]);
      hi = glm::max(hi, mesh.positions[v]);
    }
  };
  for (int f = 0; f < 1500; ++f) {
    for (int g = f + 1; g < 1500; ++g) {
      Vec3 a0, a1, b0, b1;
      box(f, a0, a1);
      box(g, b0, b1);
      if (a0.x <= b1.x && b0.x <= a1.x && a0.y <= b1.y && b0.y <= a1.y && a0.z <= b1.z && b0.z <= a1.z) {
        expected.emplace_back(f, g);
      }
    }
  }
  EXPECT_GT(expected.size(), 100u);
  EXPECT_EQ(found, expected);
}

// `count` small triangles scattered over [0, 4]^3, then a fan of six equally near coplanar faces
// straight below (0, 0, 5.5) (faces count to count + 5): ties for a query there.
TriMesh scattered_with_fan(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> u(0.0, 4.0), d(-0.4, 0.4);
  TriMesh mesh;
  for (int i = 0; i < count; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const auto base = static_cast<int32_t>(mesh.positions.size());
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + Vec3(d(rng), d(rng), d(rng)));
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  const auto centre = static_cast<int32_t>(mesh.positions.size());
  mesh.positions.emplace_back(0.0, 0.0, 5.0);
  for (int k = 0; k < 6; ++k) mesh.positions.emplace_back(std::cos(k * M_PI / 3.0), std::sin(k * M_PI / 3.0), 5.0);
  for (int k = 0; k < 6; ++k) mesh.triangles.push_back({centre, centre + 1 + k, centre + 1 + (k + 1) % 6});
  return mesh;
}

// A search with an offset answers as a BVH of the moved copy does: the same face, closest point
// and cost, bit for bit, ties included (a fan of equally near faces around one query).
TEST(FaceBvh, AnOffsetSearchAnswersAsTheMovedCopysBvh) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(0.0, 4.0);
  const TriMesh mesh = scattered_with_fan(rng, 400);
  const Vec3 offset(1.37, -2.91, 0.0);
  TriMesh moved = mesh;
  for (Vec3& p : moved.positions) p += offset;
  const FaceBvh here(mesh), there(moved);
  const auto cost = [](const ClosestPoint& c) { return 1.0 + c.distance; };
  const auto radius = [](double c) { return c - 1.0; };
  std::vector<Vec3> queries = {offset + Vec3(0.0, 0.0, 5.5)};
  for (int i = 0; i < 200; ++i) queries.push_back(offset + Vec3(u(rng), u(rng), u(rng)));
  for (const Vec3& p : queries) {
    double a = 0.0, b = 0.0;
    const ClosestPoint x = here.min_cost_face(p, cost, radius, &a, std::numeric_limits<double>::infinity(), {}, -1, offset);
    const ClosestPoint y = there.min_cost_face(p, cost, radius, &b);
    EXPECT_EQ(x.face, y.face);
    EXPECT_EQ(x.point, y.point);
    EXPECT_EQ(x.distance, y.distance);
    EXPECT_EQ(a, b);
  }
}

// A BVH over some faces of a mesh answers as brute force over those faces does, naming the mesh's
// faces: closest points, least costs with ties to the lowest mesh index (also against a known
// face of another subset), box queries and overlapping pairs.
TEST(FaceBvh, SubsetAnswersNameTheMeshFacesAsBruteForceOverTheSubset) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(0.0, 4.0);
  // The fan's faces 600-605 go into the subset in reverse, so that the lowest index is not the
  // first primitive.
  TriMesh mesh = scattered_with_fan(rng, 600);
  std::vector<int32_t> subset;
  for (int32_t f = 605; f >= 0; --f)
    if (f >= 600 || f % 3 != 0) subset.push_back(f);
  std::shuffle(subset.begin(), subset.end() - 6, rng);
  std::vector<uint8_t> in_subset(mesh.num_faces(), 0);
  for (int32_t f : subset) in_subset[f] = 1;
  const FaceBvh bvh(mesh, subset);

  const auto distance_to = [&](const Vec3& p, size_t f) {
    const Tri& t = mesh.triangles[f];
    return reference_distance(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  };
  const auto cost = [](const ClosestPoint& c) { return 1.0 + c.distance; };
  const auto radius = [](double c) { return c - 1.0; };
  for (int i = 0; i < 200; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    double nearest = std::numeric_limits<double>::infinity();
    int32_t nearest_face = -1;
    for (size_t f = 0; f < mesh.num_faces(); ++f)
      if (in_subset[f] && distance_to(p, f) < nearest) nearest = distance_to(p, f), nearest_face = static_cast<int32_t>(f);
    const ClosestPoint cp = bvh.closest_point(p);
    EXPECT_EQ(cp.face, nearest_face);
    EXPECT_NEAR(cp.distance, nearest, 1e-12);
    double best = 0.0;
    EXPECT_EQ(bvh.min_cost_face(p, cost, radius, &best).face, nearest_face);
    EXPECT_NEAR(best, 1.0 + nearest, 1e-12);
    std::vector<int32_t> found, expected;
    const Vec3 lo = p - Vec3(0.3), hi = p + Vec3(0.3);
    bvh.faces_in_box(lo, hi, found);
    for (size_t f = 0; f < mesh.num_faces(); ++f) {
      if (!in_subset[f]) continue;
      Vec3 flo(1e300), fhi(-1e300);
      for (int32_t v : mesh.triangles[f]) flo = glm::min(flo, mesh.positions[v]), fhi = glm::max(fhi, mesh.positions[v]);
      if (flo.x <= hi.x && lo.x <= fhi.x && flo.y <= hi.y && lo.y <= fhi.y && flo.z <= hi.z && lo.z <= fhi.z)
        expected.push_back(static_cast<int32_t>(f));
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected);
  }
  const Vec3 above(0.0, 0.0, 5.5);
  double best = 0.0;
  EXPECT_EQ(bvh.min_cost_face(above, cost, radius, &best).face, 600);
  EXPECT_EQ(best, 1.5);
  // Known at face 603 (or at a face outside the subset with a higher index): 600 ties lower.
  EXPECT_EQ(bvh.min_cost_face(above, cost, radius, &best, 1.5, {}, 603).face, 600);
  EXPECT_EQ(bvh.min_cost_face(above, cost, radius, &best, 1.5, {}, 700).face, 600);
  EXPECT_EQ(bvh.min_cost_face(above, cost, radius, &best, 1.5, {}, 599).face, -1);

  std::mutex m;
  std::vector<std::pair<int32_t, int32_t>> pairs, expected_pairs;
  bvh.for_each_overlapping_pair([&](int32_t f, int32_t g) {
    std::lock_guard<std::mutex> lock(m);
    pairs.emplace_back(f, g);
  });
  std::sort(pairs.begin(), pairs.end());
  const FaceBvh whole(mesh);
  whole.for_each_overlapping_pair([&](int32_t f, int32_t g) {
    std::lock_guard<std::mutex> lock(m);
    if (in_subset[f] && in_subset[g]) expected_pairs.emplace_back(f, g);
  });
  std::sort(expected_pairs.begin(), expected_pairs.end());
  EXPECT_GT(expected_pairs.size(), 10u);
  EXPECT_EQ(pairs, expected_pairs);
  EXPECT_THROW(FaceBvh(mesh, std::vector<int32_t>{606}), std::out_of_range);
}

}  // namespace
}  // namespace meshquilt
