// The matching_cost kernel (a lower bound of Eq. 1-3) on both back ends against an independent
// brute-force reference in double: every face, distance by projection onto the plane or the
// nearest edge. The bound must never exceed the reference, and must equal it near the swatch.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "device.h"
#include "core/error.h"
#include "matching_cost.h"
#include "mesh/tri_mesh.h"
#include "spatial/near_face_grid.h"
#include "spatial/normal_bins.h"
#include "support/backends.h"

namespace meshquilt {
namespace {

using engine::Backend;
using glm::dvec3;

// Per pair: float32 against double, relative (D >= 1 always).
constexpr double kTolerance = 1e-5;

// ---- the reference: brute force over all faces, in double --------------------------------

double segment_distance(dvec3 p, dvec3 a, dvec3 b) {
  const dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// Projects p onto the triangle's plane; inside (by edge-side tests) the distance is the height,
// otherwise the nearest point lies on an edge.
double triangle_distance(dvec3 p, dvec3 a, dvec3 b, dvec3 c) {
  const dvec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  const double edges = std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
  if (n2 <= 0.0) return edges;
  const dvec3 projected = p - n * (glm::dot(p - a, n) / n2);
  const bool inside = glm::dot(glm::cross(b - a, projected - a), n) >= 0.0 &&
                      glm::dot(glm::cross(c - b, projected - b), n) >= 0.0 &&
                      glm::dot(glm::cross(a - c, projected - c), n) >= 0.0;
  return inside ? std::abs(glm::dot(p - a, n)) / std::sqrt(n2) : edges;
}

// Fills in the face normals as geometry matching uses them: unit, (0, 0, 1) for a zero area.
void set_normals(MatchingSwatch& swatch) {
  swatch.normals.clear();
  for (const auto& t : swatch.triangles) {
    const dvec3 a(swatch.positions[t[0]]), b(swatch.positions[t[1]]), c(swatch.positions[t[2]]);
    const dvec3 cross = glm::cross(b - a, c - a);
    const double length = glm::length(cross);
    swatch.normals.emplace_back(length > 0.0 ? cross / length : dvec3(0.0, 0.0, 1.0));
  }
}

struct Reference {
  const MatchingSwatch& swatch;

  double point_cost(dvec3 q, dvec3 normal) const {
    double best = INFINITY;
    for (std::size_t f = 0; f < swatch.triangles.size(); ++f) {
      const auto& t = swatch.triangles[f];
      const dvec3 a(swatch.positions[t[0]]), b(swatch.positions[t[1]]), c(swatch.positions[t[2]]);
      const double d = (1.0 + swatch.lambda * triangle_distance(q, a, b, c)) *
                       (1.0 + glm::length(normal - dvec3(swatch.normals[f])));
      best = std::min(best, d);
    }
    return best;
  }

  // #T by #P, candidate-major like MatchingCost::point_costs.
  std::vector<double> point_costs(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals,
                                  const std::vector<glm::vec2>& translations) const {
    std::vector<double> costs;
    for (const glm::vec2& t : translations)
      for (std::size_t i = 0; i < points.size(); ++i)
        costs.push_back(point_cost(dvec3(points[i]) - dvec3(t.x, t.y, 0.0), dvec3(normals[i])));
    return costs;
  }
};

// The grid over the swatch's own (float) vertices, with the proportions geometry matching uses
// for a voxel edge `voxel`.
NearFaceGrid grid_for(const MatchingSwatch& swatch, double voxel, const std::vector<uint32_t>& face_groups = {}) {
  TriMesh mesh;
  for (const glm::vec3& p : swatch.positions) mesh.positions.emplace_back(p);
  for (const auto& t : swatch.triangles)
    mesh.triangles.push_back({static_cast<int32_t>(t[0]), static_cast<int32_t>(t[1]), static_cast<int32_t>(t[2])});
  return build_near_face_grid(mesh, voxel, 1.3 * voxel, 2.0 * voxel, 4.0 * voxel, 128, int64_t{1} << 18, face_groups);
}

// The swatch's faces binned by normal (as geometry matching bins them), with the swatch told
// how many bins there are, and the query's factors for them.
struct Grouped {
  NormalBins bins;
  std::vector<double> factors;
};
Grouped group_by_normal(MatchingSwatch& swatch, const std::vector<glm::vec3>& normals, int per_side) {
  Grouped grouped;
  grouped.bins = bin_normals(std::vector<Vec3>(swatch.normals.begin(), swatch.normals.end()), per_side);
  swatch.normal_bins = static_cast<uint32_t>(grouped.bins.size());
  grouped.factors.resize(normals.size() * grouped.bins.size());
  for (std::size_t i = 0; i < normals.size(); ++i)
    grouped.bins.factor_bounds(glm::normalize(Vec3(normals[i])), &grouped.factors[i * grouped.bins.size()]);
  return grouped;
}

// ---- inputs -----------------------------------------------------------------------------

struct Query {
  std::vector<glm::vec3> points;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> translations;
};

glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> gauss;
  for (;;) {
    const glm::vec3 v(gauss(rng), gauss(rng), gauss(rng));
    if (glm::length(v) > 1e-3f) return glm::normalize(v);
  }
}

// Random triangles over [0,4]x[0,3] (some long, some degenerate), random points around it,
// translations that keep some queries inside the grid and push others far outside.
MatchingSwatch random_swatch(std::mt19937& rng, int faces) {
  std::uniform_real_distribution<float> x(0.0f, 4.0f), y(0.0f, 3.0f), z(0.0f, 0.4f), size(-0.3f, 0.3f);
  MatchingSwatch swatch;
  for (int f = 0; f < faces; ++f) {
    const glm::vec3 a(x(rng), y(rng), z(rng));
    glm::vec3 b = a + glm::vec3(size(rng), size(rng), size(rng));
    glm::vec3 c = a + glm::vec3(size(rng), size(rng), size(rng));
    if (f % 17 == 0) c = a + 0.5f * (b - a);      // collinear: zero area
    if (f % 23 == 0) b = a;                       // repeated vertex
    if (f % 29 == 0) c = a + glm::vec3(1.5f, 0.2f, 0.0f);  // spans several cells
    const auto base = static_cast<std::uint32_t>(swatch.positions.size());
    swatch.positions.insert(swatch.positions.end(), {a, b, c});
    swatch.triangles.push_back({base, base + 1, base + 2});
  }
  swatch.lambda = 1.0f;
  return swatch;
}

Query random_query(std::mt19937& rng, int points, int candidates) {
  std::uniform_real_distribution<float> x(-1.0f, 5.0f), y(-1.0f, 4.0f), z(-0.3f, 0.7f), shift(-2.0f, 2.0f);
  Query query;
  for (int i = 0; i < points; ++i) {
    query.points.emplace_back(x(rng), y(rng), z(rng));
    query.normals.push_back(random_unit(rng));
  }
  for (int c = 0; c < candidates; ++c) query.translations.emplace_back(shift(rng), shift(rng));
  query.translations.emplace_back(40.0f, -25.0f);  // every query far outside the grid
  query.translations.emplace_back(0.0f, 0.0f);
  return query;
}

// A torus of radius 1 and tube 0.3 lying in x-y, as a procedural stand-in for a real swatch.
MatchingSwatch torus_swatch(int around, int tube) {
  MatchingSwatch swatch;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2.0 * M_PI * i / around, v = 2.0 * M_PI * j / tube;
      const double r = 1.0 + 0.3 * std::cos(v);
      swatch.positions.emplace_back(r * std::cos(u), r * std::sin(u), 0.3 * std::sin(v));
    }
  auto index = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * tube + (j % tube)); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      swatch.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      swatch.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  swatch.lambda = 10.0f;  // about 1 / mean edge, as the drivers set it
  return swatch;
}

// Reads a triangle OFF file; an empty swatch when the file is missing.
MatchingSwatch read_off(const std::filesystem::path& path) {
  MatchingSwatch swatch;
  std::ifstream in(path);
  std::string header;
  if (!(in >> header) || header != "OFF") return swatch;
  std::size_t vertices = 0, faces = 0, edges = 0;
  in >> vertices >> faces >> edges;
  swatch.positions.resize(vertices);
  for (auto& p : swatch.positions) in >> p.x >> p.y >> p.z;
  for (std::size_t f = 0; f < faces; ++f) {
    int n = 0;
    std::array<std::uint32_t, 3> t{};
    in >> n >> t[0] >> t[1] >> t[2];
    if (n != 3 || !in) return {};
    swatch.triangles.push_back(t);
  }
  return swatch;
}

// Output-like points: swatch vertices displaced a little, with their jittered vertex normals.
Query points_near(const MatchingSwatch& swatch, std::mt19937& rng, int points, const std::vector<glm::vec2>& shifts,
                  float spread) {
  std::vector<glm::vec3> normals(swatch.positions.size(), glm::vec3(0.0f));
  for (const auto& t : swatch.triangles) {
    const glm::vec3 n = glm::cross(swatch.positions[t[1]] - swatch.positions[t[0]],
                                   swatch.positions[t[2]] - swatch.positions[t[0]]);
    for (std::uint32_t v : t) normals[v] += n;
  }
  std::uniform_int_distribution<std::size_t> pick(0, swatch.positions.size() - 1);
  std::normal_distribution<float> jitter(0.0f, spread);
  Query query;
  for (int i = 0; i < points; ++i) {
    const std::size_t v = pick(rng);
    query.points.push_back(swatch.positions[v] + glm::vec3(jitter(rng), jitter(rng), jitter(rng)));
    const glm::vec3 n = normals[v] + glm::vec3(jitter(rng), jitter(rng), jitter(rng)) * (0.02f / spread) * glm::length(normals[v]);
    query.normals.push_back(glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1));
  }
  query.translations = shifts;
  return query;
}

// Every pair's bound is at most the reference (within float rounding), every candidate's score
// at most the reference sum; returns the share of pairs where the bound equals the reference.
double check_bound(const std::vector<float>& bounds, const std::vector<double>& expected, const char* what) {
  EXPECT_EQ(bounds.size(), expected.size()) << what;
  std::size_t above = 0, equal = 0;
  for (std::size_t k = 0; k < std::min(bounds.size(), expected.size()); ++k) {
    const double tolerance = kTolerance * expected[k];
    if (!(bounds[k] <= expected[k] + tolerance)) {
      if (++above <= 5) ADD_FAILURE() << what << " pair " << k << ": bound " << bounds[k] << " above " << expected[k];
    }
    if (std::abs(bounds[k] - expected[k]) <= tolerance) ++equal;
  }
  EXPECT_EQ(above, 0u) << what;
  return expected.empty() ? 1.0 : static_cast<double>(equal) / expected.size();
}

// ---- the tests, one body per back end ---------------------------------------------------

class MatchingCostTest : public test::BackendTest {
 protected:

  // Checks bounds and scores against the reference, with every voxel's faces in one list and
  // with them grouped by normal (which must give the same bounds: a group is passed over only
  // where none of its faces could lower the minimum); returns the share of exact pairs.
  double check_against_reference(const MatchingSwatch& plain, double voxel, const Query& query, const char* what) {
    MatchingSwatch grouped_swatch = plain;
    const Grouped grouped = group_by_normal(grouped_swatch, query.normals, 4);
    const std::vector<float> ungrouped =
        MatchingCost(device(), plain, grid_for(plain, voxel)).point_costs(query.points, query.normals, query.translations);
    const MatchingSwatch& swatch = grouped_swatch;
    MatchingCost cost(device(), swatch, grid_for(swatch, voxel, grouped.bins.bin_of));
    const std::vector<float> bounds = cost.point_costs(query.points, query.normals, query.translations, grouped.factors);
    EXPECT_EQ(bounds.size(), ungrouped.size()) << what;
    for (std::size_t k = 0; k < std::min(bounds.size(), ungrouped.size()); ++k)
      if (!(std::abs(bounds[k] - ungrouped[k]) <= kTolerance * ungrouped[k])) {
        ADD_FAILURE() << what << " pair " << k << ": grouped " << bounds[k] << ", one list " << ungrouped[k];
        break;
      }
    const std::vector<double> expected = Reference{swatch}.point_costs(query.points, query.normals, query.translations);
    const double exact_share = check_bound(bounds, expected, what);
    const std::vector<double> scores = cost.score(query.points, query.normals, query.translations, grouped.factors);
    EXPECT_EQ(scores.size(), query.translations.size());
    for (std::size_t c = 0; c < std::min(scores.size(), query.translations.size()); ++c) {
      double sum = 0.0, bound_sum = 0.0;
      for (std::size_t i = 0; i < query.points.size(); ++i) {
        sum += expected[c * query.points.size() + i];
        bound_sum += bounds[c * query.points.size() + i];
      }
      // Held in double, with no tolerance: the host prunes on it.
      EXPECT_LE(scores[c], sum) << what << " candidate " << c;
      // The margin for float rounding is small: the bound still prunes.
      EXPECT_GE(scores[c], 0.99 * bound_sum) << what << " candidate " << c;
    }
    // Pair by pair too, in double with no tolerance: the host abandons an exact evaluation on
    // the exact costs so far plus the bounds of the points left.
    const std::vector<double> pairs = cost.pair_bounds(query.points, query.normals, query.translations, grouped.factors);
    EXPECT_EQ(pairs.size(), expected.size()) << what;
    std::size_t above = 0;
    for (std::size_t k = 0; k < std::min(pairs.size(), expected.size()); ++k)
      if (!(pairs[k] <= expected[k]) && ++above <= 5)
        ADD_FAILURE() << what << " pair " << k << ": " << pairs[k] << " above " << expected[k];
    for (std::size_t c = 0; c < std::min(scores.size(), query.translations.size()); ++c) {
      double sum = 0.0;
      for (std::size_t i = 0; i < query.points.size(); ++i) sum += pairs[c * query.points.size() + i];
      EXPECT_EQ(scores[c], sum) << what << " candidate " << c;
    }
    return exact_share;
  }
};

// One triangle, every query inside the grid and the face always listed: the bound is Eq. 2.
TEST_P(MatchingCostTest, ClosedFormSingleTriangle) {
  MatchingSwatch swatch;
  swatch.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  swatch.triangles = {{0, 1, 2}};
  swatch.lambda = 2.0f;
  set_normals(swatch);
  TriMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  MatchingCost cost(device(), swatch, build_near_face_grid(mesh, 0.25, 3.0, 10.0, 10.0));
  const std::vector<glm::vec3> points = {{0.25f, 0.25f, 0.5f}, {0.25f, 0.25f, 0.5f}, {2.0f, 2.0f, 0.0f},
                                         {1.25f, 1.25f, 0.5f}};
  const std::vector<glm::vec3> normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}, {1, 0, 0}};
  const std::vector<glm::vec2> translations = {{0, 0}, {1, 1}};
  const std::vector<float> minima = cost.point_costs(points, normals, translations);
  const double far = 1.5 * std::sqrt(2.0);  // (2,2) to the hypotenuse's midpoint (0.5,0.5)
  const std::vector<double> expected = {
      1.0 + 2.0 * 0.5, (1.0 + 2.0 * 0.5) * 3.0, 1.0 + 2.0 * far,
      // (1.25,1.25,.5): nearest point (0.5,0.5,0); normal (1,0,0) vs (0,0,1) differ by sqrt(2)
      (1.0 + 2.0 * std::sqrt(2 * 0.75 * 0.75 + 0.25)) * (1.0 + std::sqrt(2.0)),
      // moved by (1,1): the first two points sit above (-0.75,-0.75), nearest the origin vertex
      (1.0 + 2.0 * std::sqrt(2 * 0.75 * 0.75 + 0.25)), (1.0 + 2.0 * std::sqrt(2 * 0.75 * 0.75 + 0.25)) * 3.0,
      1.0 + 2.0 * std::sqrt(2.0 * 0.5 * 0.5),  // (1,1,0): distance to the hypotenuse
      (1.0 + 2.0 * 0.5) * (1.0 + std::sqrt(2.0))};
  ASSERT_EQ(minima.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(minima[k], expected[k], 1e-6 * expected[k]) << k;
}

// Outside the grid the bound is the distance to the faces' box.
TEST_P(MatchingCostTest, OutsideTheGridTheBoxBounds) {
  std::mt19937 rng(4);
  MatchingSwatch swatch = random_swatch(rng, 50);
  set_normals(swatch);
  MatchingCost cost(device(), swatch, grid_for(swatch, 0.2));
  // Every face lies in [0, 4.3] x [0, 3.3] x [-0.3, 0.7]; (10, 1, 0.2) is at least 5.7 away.
  const std::vector<float> bound = cost.point_costs({{10.0f, 1.0f, 0.2f}}, {{0, 0, 1}}, {{0, 0}});
  ASSERT_EQ(bound.size(), 1u);
  EXPECT_GE(bound[0], 1.0f + 5.7f);
  EXPECT_LE(bound[0], Reference{swatch}.point_cost({10.0, 1.0, 0.2}, {0, 0, 1}) * (1.0 + kTolerance));
}

TEST_P(MatchingCostTest, RandomTrianglesStayBelowBruteForce) {
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    MatchingSwatch swatch = random_swatch(rng, 150 + 50 * static_cast<int>(seed));
    set_normals(swatch);
    const Query query = random_query(rng, 200, 14);
    check_against_reference(swatch, 0.1, query, ("seed " + std::to_string(seed)).c_str());
  }
}

TEST_P(MatchingCostTest, AnyWeightOrVoxelGivesABound) {
  std::mt19937 rng(11);
  MatchingSwatch swatch = random_swatch(rng, 120);
  set_normals(swatch);
  const Query query = random_query(rng, 80, 6);
  for (float lambda : {0.0f, 0.3f, 5.0f})
    for (double voxel : {0.05, 0.7, 10.0}) {
      swatch.lambda = lambda;
      check_against_reference(swatch, voxel, query,
                              ("lambda " + std::to_string(lambda) + " voxel " + std::to_string(voxel)).c_str());
    }
}

// Output-like points near a swatch: the lists decide nearly every pair, so the bound is Eq. 2.
TEST_P(MatchingCostTest, TorusNearTheSurfaceIsExact) {
  std::mt19937 rng(5);
  MatchingSwatch swatch = torus_swatch(40, 16);
  set_normals(swatch);
  std::vector<glm::vec2> shifts;
  for (int i = -2; i <= 2; ++i) shifts.emplace_back(i * 0.04f, -i * 0.02f);
  const double exact = check_against_reference(swatch, 0.075, points_near(swatch, rng, 300, shifts, 0.02f), "torus");
  EXPECT_GT(exact, 0.95);
}

TEST_P(MatchingCostTest, FlattenedBunnyNearTheSurfaceIsExact) {
  const std::filesystem::path file = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes/bunny.off";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  MatchingSwatch swatch = read_off(file);
  ASSERT_GT(swatch.triangles.size(), 1000u) << file;
  // Swatch frame: flatten to a slab, thinnest axis along z.
  double edges = 0.0;
  for (glm::vec3& p : swatch.positions) p = glm::vec3(p.x, p.y, 0.15f * p.z);
  for (const auto& t : swatch.triangles) edges += glm::length(swatch.positions[t[1]] - swatch.positions[t[0]]);
  const double mean_edge = edges / swatch.triangles.size();
  swatch.lambda = static_cast<float>(1.0 / mean_edge);
  set_normals(swatch);
  std::vector<glm::vec2> shifts;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) shifts.emplace_back(i * 0.1f * mean_edge, j * 0.1f * mean_edge);
  std::mt19937 rng(9);
  const double exact = check_against_reference(swatch, 0.75 * mean_edge, points_near(swatch, rng, 150, shifts, static_cast<float>(0.15 * mean_edge)), "bunny");
  EXPECT_GT(exact, 0.9);
}

TEST_P(MatchingCostTest, EmptyInputs) {
  std::mt19937 rng(3);
  MatchingSwatch swatch = random_swatch(rng, 20);
  set_normals(swatch);
  MatchingCost cost(device(), swatch, grid_for(swatch, 0.25));
  const std::vector<glm::vec3> none;
  const std::vector<glm::vec2> shifts = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(cost.score(none, none, shifts), std::vector<double>(3, 0.0));
  EXPECT_TRUE(cost.point_costs(none, none, shifts).empty());
  const std::vector<glm::vec3> one = {{1, 1, 1}};
  EXPECT_TRUE(cost.score(one, one, {}).empty());
  EXPECT_EQ(cost.last_dispatch_count(), 0u);
}

TEST_P(MatchingCostTest, RejectsBadInput) {
  MatchingSwatch swatch;
  swatch.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  swatch.triangles = {{0, 1, 2}};
  set_normals(swatch);
  const NearFaceGrid grid = grid_for(swatch, 0.25);
  swatch.triangles.clear();
  EXPECT_THROW(MatchingCost(device(), swatch, grid), InputError);  // no faces
  swatch.triangles = {{0, 1, 3}};
  EXPECT_THROW(MatchingCost(device(), swatch, grid), InputError);  // index out of range
  swatch.triangles = {{0, 1, 2}};
  swatch.normals.clear();
  EXPECT_THROW(MatchingCost(device(), swatch, grid), InputError);  // normals do not match faces
  set_normals(swatch);
  swatch.lambda = -1.0f;
  EXPECT_THROW(MatchingCost(device(), swatch, grid), InputError);
  swatch.lambda = 1.0f;
  swatch.positions[1].x = NAN;
  EXPECT_THROW(MatchingCost(device(), swatch, grid), InputError);
  swatch.positions[1].x = 1.0f;
  NearFaceGrid broken = grid;
  broken.faces.push_back(7);
  EXPECT_THROW(MatchingCost(device(), swatch, broken), InputError);  // lists a face the swatch lacks
  broken = grid;
  broken.start.pop_back();
  EXPECT_THROW(MatchingCost(device(), swatch, broken), InputError);
  MatchingCost cost(device(), swatch, grid);
  EXPECT_THROW(cost.score({{0, 0, 0}}, {}, {{0, 0}}), InputError);
  EXPECT_THROW(cost.score({{0, NAN, 0}}, {{0, 0, 1}}, {{0, 0}}), InputError);
  EXPECT_THROW(cost.score({{0, 0, 0}}, {{0, 0, INFINITY}}, {{0, 0}}), InputError);
  EXPECT_THROW(cost.score({{0, 0, 0}}, {{0, 0, 1}}, {{NAN, 0}}), InputError);
  EXPECT_THROW(cost.score({{0, 0, 0}}, {{0, 0, 1}}, {{0, 0}}, {1.0, 1.0}), InputError);  // one bin, two factors
  EXPECT_THROW(cost.score({{0, 0, 0}}, {{0, 0, 1}}, {{0, 0}}, {NAN}), InputError);
  broken = grid;
  broken.groups[0].label = 1;  // the swatch has one bin
  EXPECT_THROW(MatchingCost(device(), swatch, broken), InputError);
  EXPECT_NEAR(cost.score({{0.2f, 0.2f, 1.0f}}, {{0, 0, 1}}, {{0, 0}})[0], 2.0, 1e-4);
}

TEST_P(MatchingCostTest, BatchingDoesNotChangeResults) {
  std::mt19937 rng(21);
  MatchingSwatch swatch = random_swatch(rng, 200);
  set_normals(swatch);
  const NearFaceGrid grid = grid_for(swatch, 0.1);
  const Query query = random_query(rng, 100, 8);  // 10 candidates, 1000 pairs
  MatchingCost whole(device(), swatch, grid);
  const std::vector<float> reference = whole.point_costs(query.points, query.normals, query.translations);
  EXPECT_EQ(whole.last_dispatch_count(), 1u);
  for (const auto& [max_pairs, dispatches] : std::vector<std::pair<std::size_t, std::size_t>>{
           {250, 5},   // 2 candidates x 100 points per dispatch
           {37, 30}})  // 37 points, 1 candidate: 3 chunks x 10
  {
    MatchingCost batched(device(), swatch, grid, {max_pairs});
    EXPECT_EQ(batched.point_costs(query.points, query.normals, query.translations), reference) << max_pairs;
    EXPECT_EQ(batched.last_dispatch_count(), dispatches) << max_pairs;
    EXPECT_EQ(batched.score(query.points, query.normals, query.translations),
              whole.score(query.points, query.normals, query.translations));
  }
}

MESHQUILT_ON_BACKENDS(MatchingCostTest);

// Vulkan against its C++ twin, pair by pair.
TEST(MatchingCostParity, VulkanAgreesWithCpuTwin) {
  std::string why;
  auto vulkan = test::open_backend(Backend::vulkan, &why);
  MESHQUILT_REQUIRE_DEVICE(vulkan, why);
  auto cpu = engine::open_device(engine::BackendChoice::cpu);
  std::mt19937 rng(77);
  MatchingSwatch swatch = random_swatch(rng, 400);
  set_normals(swatch);
  const Query query = random_query(rng, 500, 30);
  const Grouped grouped = group_by_normal(swatch, query.normals, 4);
  const NearFaceGrid grid = grid_for(swatch, 0.1, grouped.bins.bin_of);
  const std::vector<float> a =
      MatchingCost(*vulkan, swatch, grid).point_costs(query.points, query.normals, query.translations, grouped.factors);
  const std::vector<float> b =
      MatchingCost(*cpu, swatch, grid).point_costs(query.points, query.normals, query.translations, grouped.factors);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    ASSERT_LE(std::abs(a[k] - b[k]), kTolerance * std::max(1.0f, std::abs(b[k]))) << k << ": " << a[k] << " vs " << b[k];
}

}  // namespace
}  // namespace meshquilt
