// Geometry matching (Section 2.4, Eq. 1-3): the host's exact cost and its faces against a brute
// force written here, recovery of a known placement, the pruned search against the full one,
// and the same choice on both back ends.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>

#include <glm/geometric.hpp>

#include "device.h"
#include "core/error.h"
#include "mesh/measures.h"
#include "quilt/geometry_matching.h"
#include "spatial/closest_point.h"
#include "swatch/chainmail.h"
#include "support/backends.h"

namespace meshquilt {
namespace {

// Scattered small tetrahedra at random positions and orientations: a swatch with no symmetry.
TriMesh random_swatch(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TriMesh mesh;
  for (int k = 0; k < count; ++k) {
    const Vec3 centre(8.0 * u(rng), 6.0 * u(rng), 0.3 * u(rng));
    const int32_t base = static_cast<int32_t>(mesh.positions.size());
    for (int v = 0; v < 4; ++v)
      mesh.positions.push_back(centre + 0.4 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    for (const Tri& t : {Tri{0, 2, 1}, Tri{0, 1, 3}, Tri{1, 2, 3}, Tri{0, 3, 2}})
      mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  return mesh;
}

// Distance from p to triangle abc: the plane when p projects inside, else the nearest edge.
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  const double area2 = glm::dot(n, n);
  if (area2 > 0.0) {
    const Vec3 q = p - n * (glm::dot(p - a, n) / area2);
    const double u = glm::dot(glm::cross(c - b, q - b), n), v = glm::dot(glm::cross(a - c, q - c), n),
                 w = glm::dot(glm::cross(b - a, q - a), n);
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) return glm::length(p - q);
  }
  auto segment = [&](const Vec3& s, const Vec3& e) {
    const double t = glm::clamp(glm::dot(p - s, e - s) / std::max(glm::dot(e - s, e - s), 1e-300), 0.0, 1.0);
    return glm::length(p - (s + t * (e - s)));
  };
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

double brute_force_cost(const TriMesh& swatch, const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                        const glm::dvec2& t, double lambda) {
  double total = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (const Tri& f : swatch.triangles) {
      const Vec3 &a = swatch.positions[f[0]], &b = swatch.positions[f[1]], &c = swatch.positions[f[2]];
      const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
      const double d = distance_to_triangle(points[i] - Vec3(t, 0.0), a, b, c);
      best = std::min(best, (1.0 + lambda * d) * (1.0 + glm::length(normals[i] - n)));
    }
    total += best;
  }
  return total;
}

TEST(GeometryMatching, ExactCostIsEquation3) {
  std::mt19937_64 rng(11);
  const TriMesh swatch = random_swatch(rng, 30);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  MatchingOptions options;
  options.lambda = 2.5;
  const GeometryMatcher matcher(*device, swatch, 0.5, options);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points, normals;
  for (int k = 0; k < 200; ++k) {
    points.emplace_back(4.0 + 4.0 * u(rng), 3.0 + 3.0 * u(rng), 0.3 * u(rng));
    normals.push_back(glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0, 0, 0.1)));
  }
  for (const glm::dvec2 t : {glm::dvec2(0.0), glm::dvec2(0.7, -0.3), glm::dvec2(-1.5, 2.0)})
    EXPECT_NEAR(matcher.exact_cost(points, normals, t), brute_force_cost(swatch, points, normals, t, 2.5), 1e-9);
}

// A flat grid of triangles (exact coordinates: points on its vertices and edges, above them and
// beyond its border are equally near several faces of one normal, so costs tie exactly) beside
// scattered tetrahedra. Per point, the exact cost's face is the lowest index among the faces of
// least cost, found here by trying every face, whatever faces are given to try first.
TEST(GeometryMatching, ExactFacesAreTheLowestIndexOfTheLeastCostWhateverTheHints) {
  std::mt19937_64 rng(23);
  TriMesh swatch = random_swatch(rng, 20);
  const int n = 12;
  const auto base = static_cast<int32_t>(swatch.positions.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) swatch.positions.emplace_back(1.0 + 0.25 * i, 1.0 + 0.25 * j, 0.5);
  const auto at = [&](int i, int j) { return base + j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      swatch.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      swatch.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  // And a tilted grid with inexact coordinates: its faces' normals differ in the last places,
  // so points on its vertices and edges are near ties that rounding decides.
  const int m = 8;
  const auto tilted = static_cast<int32_t>(swatch.positions.size());
  const Vec3 origin(5.0, 4.0, 0.2), e1(0.23, 0.031, 0.071), e2(-0.027, 0.21, 0.053);
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) swatch.positions.push_back(origin + double(i) * e1 + double(j) * e2);
  const auto on_tilted = [&](int i, int j) { return tilted + j * (m + 1) + i; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      swatch.triangles.push_back({on_tilted(i, j), on_tilted(i + 1, j), on_tilted(i + 1, j + 1)});
      swatch.triangles.push_back({on_tilted(i, j), on_tilted(i + 1, j + 1), on_tilted(i, j + 1)});
    }
  auto device = engine::open_device(engine::BackendChoice::cpu);
  MatchingOptions options;
  options.lambda = 4.0;
  const GeometryMatcher matcher(*device, swatch, 0.5, options);

  std::vector<Vec3> points, normals;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = -2; j <= 2 * n + 2; ++j)
    for (int i = -2; i <= 2 * n + 2; ++i) {
      const double lift = (i + j) % 3 == 0 ? 0.0 : ((i + j) % 3 == 1 ? 0.25 : -0.5);
      points.emplace_back(1.0 + 0.125 * i, 1.0 + 0.125 * j, 0.5 + lift);
      normals.push_back((i * j) % 2 == 0 ? Vec3(0.0, 0.0, 1.0) : glm::normalize(Vec3(u(rng), u(rng), u(rng))));
    }
  for (int k = 0; k < 300; ++k) {
    points.emplace_back(4.0 + 4.0 * u(rng), 3.0 + 3.0 * u(rng), 0.3 * u(rng));
    normals.push_back(glm::normalize(Vec3(u(rng), u(rng), u(rng))));
  }
  // On the tetrahedra and the tilted grid, at distances of rounding errors, where a bound that
  // rounding lifts above the computed distance passes over the least cost.
  const Vec3 tilted_normal = glm::normalize(glm::cross(e1, e2));
  for (size_t f = 0; f < swatch.num_faces(); ++f) {
    if (f >= 80 && static_cast<int32_t>(swatch.triangles[f][0]) < tilted) continue;  // the exact grid
    const Tri& tri = swatch.triangles[f];
    const Vec3 &a = swatch.positions[tri[0]], &b = swatch.positions[tri[1]], &c = swatch.positions[tri[2]];
    const Vec3 face_normal = f < 80 ? glm::normalize(glm::cross(b - a, c - a)) : tilted_normal;
    for (const Vec3& q : {(a + b + c) / 3.0, 0.3 * a + 0.7 * b, a, 0.5 * (a + c)}) {
      points.push_back(q);
      normals.push_back(face_normal);
    }
  }

  for (const glm::dvec2 t : {glm::dvec2(0.0), glm::dvec2(0.25, -0.125)}) {
    std::vector<int32_t> expected(points.size(), -1);
    double expected_total = 0.0;
    int tied = 0;
    for (size_t p = 0; p < points.size(); ++p) {
      const Vec3 q = points[p] - Vec3(t, 0.0);
      double best = std::numeric_limits<double>::infinity();
      int ties = 0;
      for (size_t f = 0; f < swatch.num_faces(); ++f) {
        const Tri& tri = swatch.triangles[f];
        const Vec3 &a = swatch.positions[tri[0]], &b = swatch.positions[tri[1]], &c = swatch.positions[tri[2]];
        const Vec3 cross = glm::cross(b - a, c - a);
        const Vec3 face_normal = cross / glm::length(cross);
        const double cost = (1.0 + options.lambda * closest_point_on_triangle(q, a, b, c).distance) *
                            (1.0 + glm::length(normals[p] - face_normal));
        if (cost < best) {
          best = cost;
          expected[p] = static_cast<int32_t>(f);
          ties = 0;
        } else if (cost == best) {
          ++ties;
        }
      }
      expected_total += best;
      tied += ties > 0;
    }
    ASSERT_GT(tied, 100) << "too few exact ties for the test to mean anything";
    std::vector<int32_t> fresh(points.size(), -1), hinted(points.size());
    std::uniform_int_distribution<int32_t> any_face(0, static_cast<int32_t>(swatch.num_faces()) - 1);
    for (int32_t& h : hinted) h = any_face(rng);
    EXPECT_EQ(matcher.exact_cost(points, normals, t, fresh), expected_total);
    EXPECT_EQ(matcher.exact_cost(points, normals, t, hinted), expected_total);
    for (size_t p = 0; p < points.size(); ++p) {
      ASSERT_EQ(fresh[p], expected[p]) << "point " << p;
      ASSERT_EQ(hinted[p], expected[p]) << "point " << p << " (hinted)";
    }
  }
}

// Output points copied from the swatch moved by a known translation: the match finds it.
std::vector<glm::dvec2> grid_candidates(double cell) {
  std::vector<glm::dvec2> candidates;
  for (int y = -4; y <= 4; ++y)
    for (int x = -4; x <= 4; ++x) candidates.emplace_back(x * cell, y * cell);
  return candidates;
}

void copied_points(const TriMesh& swatch, const glm::dvec2& t, std::vector<Vec3>* points, std::vector<Vec3>* normals) {
  std::vector<Vec3> n(swatch.num_vertices(), Vec3(0.0));
  for (const Tri& f : swatch.triangles)
    for (int k = 0; k < 3; ++k)
      n[f[k]] += glm::cross(swatch.positions[f[1]] - swatch.positions[f[0]], swatch.positions[f[2]] - swatch.positions[f[0]]);
  for (size_t v = 0; v < swatch.num_vertices(); ++v) {
    const Vec3 p = swatch.positions[v] + Vec3(t, 0.0);
    if (p.x < 2.0 || p.x > 6.0 || p.y < 1.5 || p.y > 4.5) continue;  // a sub-patch
    points->push_back(p);
    normals->push_back(glm::normalize(n[v]));
  }
}

TEST(GeometryMatching, FindsTheTranslationTheOutputWasCopiedWith) {
  std::mt19937_64 rng(5);
  const TriMesh swatch = random_swatch(rng, 60);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  const double cell = 0.25;
  const GeometryMatcher matcher(*device, swatch, cell);
  // On the grid, and off it by fractions of a cell (found by the continuous refinement).
  std::vector<glm::dvec2> truths = {glm::dvec2(2 * cell, -cell), glm::dvec2(0.37 * cell, 1.62 * cell)};
  std::uniform_real_distribution<double> off(-3.5 * cell, 3.5 * cell);
  for (int k = 0; k < 6; ++k) truths.emplace_back(off(rng), off(rng));
  for (const glm::dvec2 truth : truths) {
    std::vector<Vec3> points, normals;
    copied_points(swatch, truth, &points, &normals);
    ASSERT_GT(points.size(), 20u);
    std::mt19937_64 choice(1);
    const MatchResult m = matcher.match(points, normals, grid_candidates(cell), choice);
    EXPECT_NEAR(m.translation.x, truth.x, 1e-4);
    EXPECT_NEAR(m.translation.y, truth.y, 1e-4);
    EXPECT_NEAR(m.cost, matcher.exact_cost(points, normals, m.translation), 1e-9);
    EXPECT_GE(m.rescored, 1);
  }
}

// The output around a seed as the step sees it: pieces of the swatch copied at several offsets
// (seams between earlier patches), jittered, some points lifted off the swatch.
// With one piece, a periodic swatch matches equally well at many candidates.
void layered_points(const TriMesh& swatch, std::mt19937_64& rng, bool one_piece, std::vector<Vec3>* points,
                    std::vector<Vec3>* normals) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.03);
  glm::dvec2 offsets[3] = {glm::dvec2(0.31 * u(rng), 0.27 * u(rng)), glm::dvec2(0.9 * u(rng), 0.4 * u(rng)),
                           glm::dvec2(0.2 * u(rng), 0.8 * u(rng))};
  if (one_piece) offsets[1] = offsets[2] = offsets[0];
  for (int piece = 0; piece < 3; ++piece) {
    std::vector<Vec3> p, n;
    copied_points(swatch, offsets[piece], &p, &n);
    for (size_t k = 0; k < p.size(); ++k) {
      // Pieces split the sub-patch into vertical bands.
      if (static_cast<int>((p[k].x - 2.0) / 4.0 * 3.0) != piece) continue;
      Vec3 q = p[k] + Vec3(noise(rng), noise(rng), noise(rng));
      if (k % 13 == 0) q.z += 1.5;  // far from any face: the exact cost falls back to the BVH
      points->push_back(q);
      normals->push_back(glm::normalize(n[k] + Vec3(noise(rng), noise(rng), noise(rng))));
    }
  }
}

// The reference of the pruned search is the same rule with every candidate evaluated exactly:
// both must choose the same translation, cost and random draw, while the pruned one evaluates
// fewer candidates. Returns how many of its evaluations the pruned search abandoned.
int expect_pruning_changes_nothing(const TriMesh& swatch, double cell, int trials, uint64_t seed,
                                   int abandon_block = MatchingOptions{}.abandon_block) {
  auto device = engine::open_device(engine::BackendChoice::cpu);
  MatchingOptions options;
  options.lambda = 1.0 / mean_edge_length(swatch);  // as the drivers set it
  options.abandon_block = abandon_block;
  MatchingOptions full = options;
  full.prune = false;
  const GeometryMatcher pruned(*device, swatch, cell, options), reference(*device, swatch, cell, full);
  std::mt19937_64 rng(seed);
  int fewer = 0, near = 0, abandoned = 0;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Vec3> points, normals;
    layered_points(swatch, rng, trial % 2 == 1, &points, &normals);
    if (points.size() <= 20u) {
      ADD_FAILURE() << "trial " << trial << ": " << points.size() << " points";
      return 0;
    }
    const std::vector<glm::dvec2> candidates = grid_candidates(cell);
    std::mt19937_64 a(trial), b(trial);
    const MatchResult x = pruned.match(points, normals, candidates, a);
    const MatchResult y = reference.match(points, normals, candidates, b);
    EXPECT_EQ(x.translation, y.translation) << "trial " << trial;
    EXPECT_EQ(x.cost, y.cost) << "trial " << trial;
    EXPECT_EQ(a(), b()) << "trial " << trial;
    EXPECT_EQ(x.near, y.near) << "trial " << trial;
    near += x.near;
    EXPECT_EQ(y.rescored, static_cast<int>(candidates.size()));
    EXPECT_EQ(y.abandoned, 0);
    if (x.rescored < y.rescored) ++fewer;
    abandoned += x.abandoned;
  }
  EXPECT_GT(fewer, trials / 2);
  EXPECT_GT(near, trials) << "the near sets were single candidates: the test would not see a lost one";
  return abandoned;
}

TEST(GeometryMatching, PrunedSearchChoosesWhatTheFullSearchChoosesOnRandomSwatches) {
  std::mt19937_64 rng(17);
  expect_pruning_changes_nothing(random_swatch(rng, 80), 0.25, 12, 3);
}

// Evaluations abandoned between blocks of a few points (on real jobs a block is an eighth of
// thousands) leave every choice as the full search makes it.
TEST(GeometryMatching, AbandonedEvaluationsChangeNoChoice) {
  std::mt19937_64 rng(23);
  EXPECT_GT(expect_pruning_changes_nothing(random_swatch(rng, 80), 0.25, 12, 5, 4), 12);
  ChainmailOptions options = ChainmailOptions::small();
  options.rows = 4;
  options.columns = 6;
  EXPECT_GT(expect_pruning_changes_nothing(make_chainmail(options), 0.3, 5, 6, 16), 5);
}

TEST(GeometryMatching, PrunedSearchChoosesWhatTheFullSearchChoosesOnChainMail) {
  // A periodic swatch: many candidates cost nearly the same, so ties and near-ties are tested.
  ChainmailOptions options = ChainmailOptions::small();
  options.rows = 4;
  options.columns = 6;
  const TriMesh swatch = make_chainmail(options);
  expect_pruning_changes_nothing(swatch, 0.3, 5, 4);
}

// A matcher whose grid was read from a folder, one that wrote it there and one that built it
// alone choose alike (translation, cost, random draw).
TEST(GeometryMatching, AGridReadFromAFolderChoosesWhatABuiltOneChooses) {
  ChainmailOptions chain = ChainmailOptions::small();
  chain.rows = 4;
  chain.columns = 6;
  const TriMesh swatch = make_chainmail(chain);
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("meshquilt_matching_grids_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  MatchingOptions options;
  options.lambda = 1.0 / mean_edge_length(swatch);
  MatchingOptions cached = options;
  cached.grid_folder = folder;
  const GeometryMatcher built(*device, swatch, 0.3, options), writer(*device, swatch, 0.3, cached),
      reader(*device, swatch, 0.3, cached);
  EXPECT_EQ(built.grid_source(), GridSource::built);
  EXPECT_EQ(writer.grid_source(), GridSource::written);
  EXPECT_EQ(reader.grid_source(), GridSource::read);
  std::mt19937_64 rng(8);
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<Vec3> points, normals;
    layered_points(swatch, rng, trial % 2 == 1, &points, &normals);
    const std::vector<glm::dvec2> candidates = grid_candidates(0.3);
    std::mt19937_64 a(trial), b(trial), c(trial);
    const MatchResult x = built.match(points, normals, candidates, a);
    const MatchResult y = writer.match(points, normals, candidates, b);
    const MatchResult z = reader.match(points, normals, candidates, c);
    EXPECT_EQ(x.translation, z.translation) << "trial " << trial;
    EXPECT_EQ(x.cost, z.cost) << "trial " << trial;
    EXPECT_EQ(x.rescored, z.rescored) << "trial " << trial;
    EXPECT_EQ(y.translation, z.translation) << "trial " << trial;
    const uint64_t next = c();
    EXPECT_EQ(a(), next) << "trial " << trial;
    EXPECT_EQ(b(), next) << "trial " << trial;
  }
  std::filesystem::remove_all(folder);
}

TEST(GeometryMatching, LinesUpAPeriodicSwatchOffTheGrid) {
  // Chain mail copied at translations that are no whole number of cells: equally good
  // placements recur with the lattice, so the match must cost what the true one costs (Eq. 3 is
  // smallest there: every point lies on the swatch), wherever it lands.
  ChainmailOptions chain = ChainmailOptions::small();
  chain.rows = 4;
  chain.columns = 6;
  const TriMesh swatch = make_chainmail(chain);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  MatchingOptions options;
  options.lambda = 1.0 / mean_edge_length(swatch);
  options.choose_tolerance = 0.0;  // the best refined minimum, not a pick among the near-best
  const double cell = 0.3;
  const GeometryMatcher matcher(*device, swatch, cell, options);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> off(-3.5 * cell, 3.5 * cell);
  for (int k = 0; k < 6; ++k) {
    const glm::dvec2 truth(off(rng), off(rng));
    std::vector<Vec3> points, normals;
    copied_points(swatch, truth, &points, &normals);
    ASSERT_GT(points.size(), 20u);
    std::mt19937_64 choice(k);
    const MatchResult m = matcher.match(points, normals, grid_candidates(cell), choice);
    EXPECT_LE(m.cost, matcher.exact_cost(points, normals, truth) * (1.0 + 1e-6)) << "truth " << truth.x << ", " << truth.y;
  }
}

// Without refinement the choice is one of the candidates as given: the one the output was
// copied with, when it is among them with others off by fractions of a cell.
TEST(GeometryMatching, UnrefinedChoiceIsACandidateAsGiven) {
  std::mt19937_64 rng(5);
  const TriMesh swatch = random_swatch(rng, 60);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  const double cell = 0.25;
  const GeometryMatcher matcher(*device, swatch, cell);
  const glm::dvec2 truth(0.37 * cell, -1.62 * cell);
  std::vector<Vec3> points, normals;
  copied_points(swatch, truth, &points, &normals);
  ASSERT_GT(points.size(), 20u);
  const std::vector<glm::dvec2> candidates = {truth + glm::dvec2(3.3 * cell, 0.0), truth, truth + glm::dvec2(0.4 * cell, 0.3 * cell)};
  std::mt19937_64 choice(1);
  const MatchResult unrefined = matcher.match(points, normals, candidates, choice, false);
  EXPECT_EQ(unrefined.translation, truth);
  // Refined from the third candidate alone, the choice moves off it.
  std::mt19937_64 again(1);
  const MatchResult refined = matcher.match(points, normals, {candidates[2]}, again, true);
  EXPECT_NE(refined.translation, candidates[2]);
}

TEST(GeometryMatching, EmptySubPatchTakesASeededRandomCandidate) {
  std::mt19937_64 rng(3);
  const TriMesh swatch = random_swatch(rng, 10);
  auto device = engine::open_device(engine::BackendChoice::cpu);
  const GeometryMatcher matcher(*device, swatch, 0.25);
  const auto candidates = grid_candidates(0.25);
  std::mt19937_64 a(9), b(9);
  const glm::dvec2 first = matcher.match({}, {}, candidates, a).translation;
  EXPECT_EQ(first, matcher.match({}, {}, candidates, b).translation);
  EXPECT_NE(std::find(candidates.begin(), candidates.end(), first), candidates.end());
}

TEST(GeometryMatching, BothBackEndsChooseAlike) {
  std::string why;
  const std::unique_ptr<engine::Device> vulkan = test::open_backend(engine::Backend::vulkan, &why);
  MESHQUILT_REQUIRE_DEVICE(vulkan, why);
  auto cpu = engine::open_device(engine::BackendChoice::cpu);
  std::mt19937_64 rng(21);
  const TriMesh swatch = random_swatch(rng, 60);
  const GeometryMatcher on_cpu(*cpu, swatch, 0.25), on_vulkan(*vulkan, swatch, 0.25);
  for (int trial = 0; trial < 4; ++trial) {
    // Noisy copies, so that several candidates are close.
    std::vector<Vec3> points, normals;
    copied_points(swatch, glm::dvec2(0.1 * trial, -0.05 * trial), &points, &normals);
    std::normal_distribution<double> noise(0.0, 0.02);
    for (Vec3& p : points) p += Vec3(noise(rng), noise(rng), noise(rng));
    std::mt19937_64 a(trial), b(trial);
    const MatchResult x = on_cpu.match(points, normals, grid_candidates(0.25), a);
    const MatchResult y = on_vulkan.match(points, normals, grid_candidates(0.25), b);
    EXPECT_EQ(x.translation, y.translation);
    EXPECT_EQ(x.cost, y.cost);
  }
}

}  // namespace
}  // namespace meshquilt
