// The stretch_linesearch kernel (random line searches on the L2 stretch of a shell map, Sec. 3.2
// of Zhou et al. 2006) on both back ends. Shell maps are built here from planar base meshes,
// independently of the kernel, and energies and determinants are measured in double with this
// file's own 3x3 inverse.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "device.h"
#include "core/error.h"
#include "stretch_linesearch.h"
#include "support/backends.h"

namespace {

using glm::dvec2;
using glm::dvec3;
using meshquilt::InputError;
using meshquilt::StretchProblem;
using meshquilt::StretchSearchOptions;
using meshquilt::engine::Backend;
using meshquilt::kernels::stretch_linesearch_layout::StretchTet;
// The fixture below takes the host class's name, so test names read StretchLineSearch.*.
using Search = meshquilt::StretchLineSearch;
using Colours = std::vector<std::vector<uint32_t>>;
using Matrix = std::array<std::array<double, 3>, 3>;  // [row][column]


// ---- shell maps over planar base meshes ---------------------------------------------------

struct BaseMesh {
  std::vector<dvec2> uv;                           // #A positions in the plane = bottom uv
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise
  std::vector<bool> boundary;                      // #A
};

// The shell position of corner (vertex, layer): layer 0 bottom, 1 top.
using Shell = std::function<dvec3(uint32_t vertex, int layer)>;

struct ShellMap {
  StretchProblem problem;
  std::vector<glm::vec2> top_uv;  // the initial map: top_uv = bottom_uv
  std::vector<bool> boundary;
};

uint32_t code(uint32_t vertex, int layer) { return 2 * vertex + static_cast<uint32_t>(layer); }

double det3(dvec3 a, dvec3 b, dvec3 c) { return glm::dot(a, glm::cross(b, c)); }

// Prisms split into three tets by the global order of their vertices, so neighbouring prisms
// agree on the diagonals of their shared sides; an odd sorting permutation swaps the first two
// corners of each tet to keep volumes positive. Weight = shell tet volume / 3.
ShellMap build_shell_map(const BaseMesh& base, const Shell& shell, float texture_height) {
  ShellMap map;
  StretchProblem& problem = map.problem;
  for (const dvec2& p : base.uv) problem.bottom_uv.emplace_back(p);
  problem.texture_height = texture_height;
  for (const auto& face : base.triangles) {
    std::array<int, 3> k = {0, 1, 2};
    std::sort(k.begin(), k.end(), [&](int i, int j) { return face[i] < face[j]; });
    const bool odd = !((k[0] == 0 && k[1] == 1) || (k[0] == 1 && k[1] == 2) || (k[0] == 2 && k[1] == 0));
    const auto b = [&](int i) { return std::make_pair(face[k[i]], 0); };
    const auto t = [&](int i) { return std::make_pair(face[k[i]], 1); };
    std::vector<std::array<std::pair<uint32_t, int>, 4>> tets = {
        {b(0), b(1), b(2), t(2)}, {b(0), b(1), t(2), t(1)}, {b(0), t(0), t(1), t(2)}};
    for (auto& tet : tets) {
      if (odd) std::swap(tet[0], tet[1]);
      const dvec3 s0 = shell(tet[0].first, tet[0].second);
      const dvec3 e1 = shell(tet[1].first, tet[1].second) - s0;
      const dvec3 e2 = shell(tet[2].first, tet[2].second) - s0;
      const dvec3 e3 = shell(tet[3].first, tet[3].second) - s0;
      const double volume = det3(e1, e2, e3) / 6.0;
      StretchTet out{};
      out.corners = glm::uvec4(code(tet[0].first, tet[0].second), code(tet[1].first, tet[1].second),
                               code(tet[2].first, tet[2].second), code(tet[3].first, tet[3].second));
      out.s0 = glm::vec4(glm::vec3(e1), static_cast<float>(volume / 3.0));
      out.s1 = glm::vec4(glm::vec3(e2), 0.0f);
      out.s2 = glm::vec4(glm::vec3(e3), 0.0f);
      problem.tets.push_back(out);
    }
  }
  const auto vertex_count = static_cast<uint32_t>(base.uv.size());
  problem.vertex_tet_offsets.push_back(0);
  for (uint32_t a = 0; a < vertex_count; ++a) {
    for (uint32_t t = 0; t < problem.tets.size(); ++t) {
      const glm::uvec4 c = problem.tets[t].corners;
      if (c.x == code(a, 1) || c.y == code(a, 1) || c.z == code(a, 1) || c.w == code(a, 1))
        problem.vertex_tets.push_back(t);
    }
    problem.vertex_tet_offsets.push_back(static_cast<uint32_t>(problem.vertex_tets.size()));
  }
  map.top_uv = problem.bottom_uv;
  map.boundary = base.boundary;
  return map;
}

// n x n vertices `spacing` apart, each square split into two counter-clockwise triangles.
BaseMesh grid(int n, double spacing) {
  BaseMesh base;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      base.uv.emplace_back(spacing * x, spacing * y);
      base.boundary.push_back(x == 0 || y == 0 || x == n - 1 || y == n - 1);
    }
  const auto at = [n](int x, int y) { return static_cast<uint32_t>(y * n + x); };
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      base.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      base.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  return base;
}

// The grid over a bumpy height field, thickened by 0.5 along the unit normal, with the top layer
// widened by 1.2 about the centre: the initial map stretches everywhere. It spans
// (n - 1) * spacing units.
ShellMap bumpy_grid(int n = 7, double spacing = 1.0) {
  const BaseMesh base = grid(n, spacing);
  const double centre = 0.5 * (n - 1) * spacing;
  const Shell shell = [&base, centre](uint32_t v, int layer) {
    const double x = base.uv[v].x, y = base.uv[v].y;
    const dvec3 bottom(x, y, 0.4 * std::sin(0.9 * x) * std::cos(0.7 * y));
    if (layer == 0) return bottom;
    const dvec3 normal = glm::normalize(dvec3(-0.36 * std::cos(0.9 * x) * std::cos(0.7 * y),
                                              0.28 * std::sin(0.9 * x) * std::sin(0.7 * y), 1.0));
    const dvec3 top = bottom + 0.5 * normal;
    return dvec3(centre + 1.2 * (top.x - centre), centre + 1.2 * (top.y - centre), top.z);
  };
  return build_shell_map(base, shell, 0.5f);
}

// A regular hexagonal fan around vertex 0 whose shell is one linear map A of texture space
// (a rotation about z times a scale, 1.3 in the plane and 0.8 in height) applied to the fan
// with the centre's top corner at `optimum`. With the centre's top uv there every tet has
// Jacobian A, and because A^T A does not mix the plane with the height, the planar gradient there
// is A^T A times the integral of the centre corner's hat function's gradient over its star, which
// has no planar part: `optimum` is the minimum.
ShellMap hexagonal_fan(dvec2 optimum = {0.0, 0.0}) {
  BaseMesh base;
  base.uv.emplace_back(0.0, 0.0);
  base.boundary.push_back(false);
  for (int k = 0; k < 6; ++k) {
    base.uv.emplace_back(std::cos(k * M_PI / 3.0), std::sin(k * M_PI / 3.0));
    base.boundary.push_back(true);
  }
  for (uint32_t k = 1; k <= 6; ++k) base.triangles.push_back({0, k, k % 6 + 1});
  const double angle = 0.4, height = 0.6;
  const Shell shell = [&base, angle, height, optimum](uint32_t v, int layer) {
    const dvec3 q(v == 0 && layer == 1 ? optimum : base.uv[v], layer * height);
    return dvec3(1.3 * (std::cos(angle) * q.x - std::sin(angle) * q.y),
                 1.3 * (std::sin(angle) * q.x + std::cos(angle) * q.y), 0.8 * q.z);
  };
  return build_shell_map(base, shell, static_cast<float>(height));
}

// Greedy colouring of `movable` vertices: a vertex takes the first colour none of the vertices
// sharing a tet with it has.
Colours greedy_colours(const StretchProblem& problem, const std::vector<uint32_t>& movable) {
  std::vector<std::set<uint32_t>> neighbours(problem.bottom_uv.size());
  for (const StretchTet& tet : problem.tets) {
    std::vector<uint32_t> tops;
    for (uint32_t c : {tet.corners.x, tet.corners.y, tet.corners.z, tet.corners.w})
      if (c & 1u) tops.push_back(c >> 1);
    for (uint32_t a : tops)
      for (uint32_t b : tops)
        if (a != b) neighbours[a].insert(b);
  }
  std::map<uint32_t, std::size_t> colour_of;
  Colours colours;
  for (uint32_t a : movable) {
    std::set<std::size_t> taken;
    for (uint32_t b : neighbours[a])
      if (colour_of.count(b)) taken.insert(colour_of[b]);
    std::size_t c = 0;
    while (taken.count(c)) ++c;
    if (c == colours.size()) colours.emplace_back();
    colours[c].push_back(a);
    colour_of[a] = c;
  }
  return colours;
}

std::vector<uint32_t> interior(const ShellMap& map) {
  std::vector<uint32_t> vertices;
  for (uint32_t a = 0; a < map.boundary.size(); ++a)
    if (!map.boundary[a]) vertices.push_back(a);
  return vertices;
}

// ---- the reference: energy and determinants in double -------------------------------------

// Gauss-Jordan elimination with partial pivoting.
Matrix inverse(Matrix m) {
  Matrix inv = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row)
      if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
    std::swap(m[col], m[pivot]);
    std::swap(inv[col], inv[pivot]);
    const double scale = 1.0 / m[col][col];
    for (int j = 0; j < 3; ++j) {
      m[col][j] *= scale;
      inv[col][j] *= scale;
    }
    for (int row = 0; row < 3; ++row) {
      if (row == col) continue;
      const double factor = m[row][col];
      for (int j = 0; j < 3; ++j) {
        m[row][j] -= factor * m[col][j];
        inv[row][j] -= factor * inv[col][j];
      }
    }
  }
  return inv;
}

using TopUv = std::vector<dvec2>;  // top uvs in double, for the reference

TopUv widen(const std::vector<glm::vec2>& top_uv) { return TopUv(top_uv.begin(), top_uv.end()); }

dvec3 texture_corner(const StretchProblem& problem, const TopUv& top_uv, uint32_t c) {
  const uint32_t v = c / 2;
  return c % 2 ? dvec3(top_uv[v], problem.texture_height) : dvec3(dvec2(problem.bottom_uv[v]), 0.0);
}

Matrix texture_edges(const StretchProblem& problem, const TopUv& top_uv, const StretchTet& tet) {
  const dvec3 q0 = texture_corner(problem, top_uv, tet.corners.x);
  const dvec3 e[3] = {texture_corner(problem, top_uv, tet.corners.y) - q0,
                      texture_corner(problem, top_uv, tet.corners.z) - q0,
                      texture_corner(problem, top_uv, tet.corners.w) - q0};
  Matrix m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = e[j][i];
  return m;
}

double texture_det(const StretchProblem& problem, const TopUv& top_uv, const StretchTet& tet) {
  const Matrix m = texture_edges(problem, top_uv, tet);
  return det3(dvec3(m[0][0], m[1][0], m[2][0]), dvec3(m[0][1], m[1][1], m[2][1]),
              dvec3(m[0][2], m[1][2], m[2][2]));
}

std::vector<double> texture_dets(const StretchProblem& problem, const std::vector<glm::vec2>& top_uv) {
  std::vector<double> dets;
  for (const StretchTet& tet : problem.tets) dets.push_back(texture_det(problem, widen(top_uv), tet));
  return dets;
}

// Sum over tets of w |S T^-1|_F^2.
double total_energy(const StretchProblem& problem, const TopUv& top_uv) {
  double sum = 0.0;
  for (const StretchTet& tet : problem.tets) {
    const Matrix t_inverse = inverse(texture_edges(problem, top_uv, tet));
    const dvec3 s[3] = {dvec3(tet.s0), dvec3(tet.s1), dvec3(tet.s2)};
    double frobenius2 = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double entry = 0.0;
        for (int k = 0; k < 3; ++k) entry += s[k][i] * t_inverse[k][j];
        frobenius2 += entry * entry;
      }
    sum += tet.s0.w * frobenius2;
  }
  return sum;
}

double total_energy(const StretchProblem& problem, const std::vector<glm::vec2>& top_uv) {
  return total_energy(problem, widen(top_uv));
}

// ---- the search as the spec states it, for one vertex ------------------------------------

uint32_t pcg_hash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// The search direction of vertex a in sweep `iteration`.
dvec2 direction(uint64_t seed, uint32_t iteration, uint32_t a) {
  const uint32_t h =
      pcg_hash(a ^ pcg_hash(iteration ^ pcg_hash(static_cast<uint32_t>(seed) ^
                                                 pcg_hash(static_cast<uint32_t>(seed >> 32)))));
  const float angle = static_cast<float>(h) * (6.28318530718f / 4294967296.0f);
  return {std::cos(static_cast<double>(angle)), std::sin(static_cast<double>(angle))};
}

// The feasible step interval of vertex a along d: every tet holding its top corner keeps
// det >= ratio * det(0) (det is linear in the step), and |t| <= the largest uv distance from the
// corner to the other corners of those tets. `reach_binds` says whether that distance cut it.
struct Interval {
  double lo = -INFINITY;
  double hi = INFINITY;
  bool reach_binds = false;
};

Interval feasible_interval(const StretchProblem& problem, const TopUv& top_uv, uint32_t a, dvec2 d,
                           double ratio) {
  Interval interval;
  TopUv moved = top_uv;
  moved[a] += d;
  double reach = 0.0;
  for (const StretchTet& tet : problem.tets) {
    const uint32_t corners[4] = {tet.corners.x, tet.corners.y, tet.corners.z, tet.corners.w};
    if (std::find(std::begin(corners), std::end(corners), code(a, 1)) == std::end(corners)) continue;
    const double det0 = texture_det(problem, top_uv, tet);
    const double det1 = texture_det(problem, moved, tet) - det0;
    if (det1 > 0.0) interval.lo = std::max(interval.lo, -(1.0 - ratio) * det0 / det1);
    if (det1 < 0.0) interval.hi = std::min(interval.hi, (1.0 - ratio) * det0 / -det1);
    for (uint32_t c : corners)
      if (c != code(a, 1))
        reach = std::max(reach, glm::length(dvec2(texture_corner(problem, top_uv, c)) - top_uv[a]));
  }
  interval.reach_binds = -reach > interval.lo || reach < interval.hi;
  interval.lo = std::max(interval.lo, -reach);
  interval.hi = std::min(interval.hi, reach);
  return interval;
}

// ---- the tests --------------------------------------------------------------------------

// One fixture for every test, so all are named StretchLineSearch.*: value-parameterized tests
// run one body per back end (Backends/StretchLineSearch.X/cpu, .../vulkan); the plain ones open
// what they need through shared_device().
class StretchLineSearch : public meshquilt::test::BackendTest {};

TEST_P(StretchLineSearch, EnergyDecreasesWithoutInverting) {
  const ShellMap map = bumpy_grid();
  const Colours colours = greedy_colours(map.problem, interior(map));
  ASSERT_GE(colours.size(), 2u);
  const double before = total_energy(map.problem, map.top_uv);
  for (double det : texture_dets(map.problem, map.top_uv)) ASSERT_GT(det, 0.0);
  Search search(device(), map.problem);

  std::vector<glm::vec2> short_run = map.top_uv;
  search.run(short_run, colours, {.sweeps = 3});
  EXPECT_EQ(search.last_dispatch_count(), 3 * colours.size());
  std::vector<glm::vec2> top_uv = map.top_uv;
  search.run(top_uv, colours, {.sweeps = 20});
  EXPECT_EQ(search.last_dispatch_count(), 20 * colours.size());

  const double after_short = total_energy(map.problem, short_run);
  const double after = total_energy(map.problem, top_uv);
  EXPECT_LT(after_short, 0.98 * before);
  // Searches only accept moves that lower the energy, and the long run starts as the short one.
  EXPECT_LE(after, after_short * (1.0 + 1e-6));
  EXPECT_LT(after, 0.98 * before);
  for (double det : texture_dets(map.problem, top_uv)) EXPECT_GT(det, 0.0);
}

// One colour and one sweep: each tet holds at most one moving corner, so its determinant may
// fall to min_volume_ratio of its start and no further.
TEST_P(StretchLineSearch, MovesKeepTheVolumeRatio) {
  ShellMap map = bumpy_grid();
  // Start far from the optimum, so the searches want long steps.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  for (uint32_t a : interior(map)) map.top_uv[a] += glm::vec2(jitter(rng), jitter(rng));
  const Colours colours = {greedy_colours(map.problem, interior(map)).front()};
  const std::vector<double> start = texture_dets(map.problem, map.top_uv);
  Search search(device(), map.problem);
  auto smallest_ratio = [&](float ratio) {
    std::vector<glm::vec2> top_uv = map.top_uv;
    search.run(top_uv, colours, {.sweeps = 1, .min_volume_ratio = ratio});
    const std::vector<double> dets = texture_dets(map.problem, top_uv);
    double smallest = INFINITY;
    for (std::size_t t = 0; t < dets.size(); ++t) smallest = std::min(smallest, dets[t] / start[t]);
    return smallest;
  };
  EXPECT_GE(smallest_ratio(0.9f), 0.9 * (1.0 - 1e-4));
  // Without the bound, some searches would go further: the bound is what held them.
  EXPECT_LT(smallest_ratio(0.0f), 0.85);
}

// The fan's minimum is known in closed form (see hexagonal_fan): at its centre, and off it.
TEST_P(StretchLineSearch, HexagonalFanReturnsToItsOptimum) {
  for (const dvec2 optimum : {dvec2(0.0, 0.0), dvec2(0.3, 0.2)}) {
    ShellMap map = hexagonal_fan(optimum);
    map.top_uv[0] = glm::vec2(optimum);
    const double least = total_energy(map.problem, map.top_uv);
    map.top_uv[0] += glm::vec2(0.22f, -0.17f);
    ASSERT_GT(total_energy(map.problem, map.top_uv), least * (1.0 + 1e-3));
    Search search(device(), map.problem);
    search.run(map.top_uv, {{0}}, {.sweeps = 60});
    // Float32 line minima resolve about sqrt(float epsilon) of the unit ring.
    EXPECT_NEAR(map.top_uv[0].x, optimum.x, 5e-4) << optimum.x;
    EXPECT_NEAR(map.top_uv[0].y, optimum.y, 5e-4) << optimum.x;
    EXPECT_NEAR(total_energy(map.problem, map.top_uv), least, 1e-6 * least) << optimum.x;
    for (uint32_t a = 1; a <= 6; ++a) EXPECT_EQ(map.top_uv[a], map.problem.bottom_uv[a]) << a;
  }
}

// With no golden-section steps a search tries the middle of its feasible interval and keeps it
// only if the energy drops: the direction, the interval (volume bound and reach) and the
// acceptance all show, against the spec's formulas evaluated here in double.
TEST_P(StretchLineSearch, BlindStepsTryTheMiddleOfTheFeasibleInterval) {
  struct Case {
    ShellMap map;
    uint32_t vertex;
    glm::vec2 start;
  };
  // The centre away from its optimum (most middles are better), at an optimum off the fan's
  // centre (every middle is worse), and a ring vertex, whose open star lets the reach cut the
  // interval where no tet would shrink.
  const Case cases[] = {{hexagonal_fan(), 0, {0.3f, 0.2f}},
                        {hexagonal_fan({0.3, 0.2}), 0, {0.3f, 0.2f}},
                        {hexagonal_fan(), 1, {1.0f, 0.0f}}};
  int moved = 0, stayed = 0, reach_cut = 0;
  for (const Case& c : cases) {
    std::vector<glm::vec2> top_uv = c.map.top_uv;
    top_uv[c.vertex] = c.start;
    const TopUv start = widen(top_uv);
    const double before = total_energy(c.map.problem, start);
    Search search(device(), c.map.problem);
    for (float ratio : {0.0f, 0.25f, 0.8f})
      for (uint64_t seed = 1; seed <= 12; ++seed) {
        const dvec2 d = direction(seed, 0, c.vertex);
        const Interval interval = feasible_interval(c.map.problem, start, c.vertex, d, ratio);
        TopUv middle = start;
        middle[c.vertex] += 0.5 * (interval.lo + interval.hi) * d;
        const double after = total_energy(c.map.problem, middle);
        if (std::abs(after - before) < 1e-5 * before) continue;  // too close to call in float32
        std::vector<glm::vec2> result = top_uv;
        search.run(result, {{c.vertex}},
                   {.sweeps = 1, .seed = seed, .golden_steps = 0, .min_volume_ratio = ratio});
        const dvec2 expected = after < before ? middle[c.vertex] : start[c.vertex];
        EXPECT_NEAR(result[c.vertex].x, expected.x, 1e-5)
            << "vertex " << c.vertex << " ratio " << ratio << " seed " << seed;
        EXPECT_NEAR(result[c.vertex].y, expected.y, 1e-5)
            << "vertex " << c.vertex << " ratio " << ratio << " seed " << seed;
        ++(after < before ? moved : stayed);
        reach_cut += after < before && interval.reach_binds;
      }
  }
  // The cases cover both outcomes and intervals cut by the reach.
  EXPECT_GT(moved, 10);
  EXPECT_GT(stayed, 10);
  EXPECT_GT(reach_cut, 5);
}

TEST_P(StretchLineSearch, UncolouredVerticesNeverMove) {
  const ShellMap map = bumpy_grid();
  std::vector<uint32_t> some;
  for (uint32_t a : interior(map))
    if (a % 2 == 0) some.push_back(a);
  const Colours colours = greedy_colours(map.problem, some);
  std::vector<glm::vec2> top_uv = map.top_uv;
  Search search(device(), map.problem);
  search.run(top_uv, colours, {.sweeps = 5});
  std::size_t moved = 0;
  for (uint32_t a = 0; a < top_uv.size(); ++a) {
    if (std::find(some.begin(), some.end(), a) != some.end()) {
      moved += top_uv[a] != map.top_uv[a];
    } else {
      EXPECT_EQ(top_uv[a].x, map.top_uv[a].x) << a;
      EXPECT_EQ(top_uv[a].y, map.top_uv[a].y) << a;
    }
  }
  EXPECT_EQ(moved, some.size());
  // No colours, or no sweeps: nothing is dispatched and nothing moves.
  top_uv = map.top_uv;
  search.run(top_uv, {}, {});
  EXPECT_EQ(search.last_dispatch_count(), 0u);
  search.run(top_uv, colours, {.sweeps = 0});
  EXPECT_EQ(search.last_dispatch_count(), 0u);
  EXPECT_EQ(top_uv, map.top_uv);
}

TEST_P(StretchLineSearch, RejectsBadInput) {
  const ShellMap map = bumpy_grid();
  const auto rejects = [&](const std::function<void(StretchProblem&)>& edit, const char* what) {
    StretchProblem problem = map.problem;
    edit(problem);
    EXPECT_THROW(Search(device(), problem), InputError) << what;
  };
  rejects([](StretchProblem& p) { p.tets[5].corners.z = static_cast<uint32_t>(2 * p.bottom_uv.size()); },
          "corner code out of range");
  rejects([](StretchProblem& p) { p.tets[5].corners.z = p.tets[5].corners.x; }, "repeated corner");
  rejects([](StretchProblem& p) { p.vertex_tet_offsets.back() -= 1; }, "offsets end before vertex_tets");
  rejects([](StretchProblem& p) { p.vertex_tets.push_back(0); }, "vertex_tets longer than the offsets");
  rejects([](StretchProblem& p) { p.vertex_tet_offsets.pop_back(); }, "offsets not #A + 1");
  rejects([](StretchProblem& p) { p.bottom_uv.pop_back(); }, "bottom_uv not #A");
  rejects([](StretchProblem& p) { std::swap(p.vertex_tets[0], p.vertex_tets.back()); },
          "a tet lacking the corner");
  rejects([](StretchProblem& p) { p.tets[2].s0.w = 0.0f; }, "zero weight");
  rejects([](StretchProblem& p) { p.tets[2].s1.y = NAN; }, "non-finite shell edge");
  rejects([](StretchProblem& p) { p.bottom_uv[3].x = INFINITY; }, "non-finite bottom uv");
  rejects([](StretchProblem& p) { p.texture_height = 0.0f; }, "zero height");

  Search search(device(), map.problem);
  const std::vector<uint32_t> inner = interior(map);
  std::vector<glm::vec2> top_uv = map.top_uv;
  EXPECT_THROW(search.run(top_uv, {{inner[0]}, {inner[0]}}, {}), InputError);  // one vertex, two colours
  EXPECT_THROW(search.run(top_uv, {{inner[0], inner[1]}}, {}), InputError);    // neighbours share a tet
  EXPECT_THROW(search.run(top_uv, {{static_cast<uint32_t>(top_uv.size())}}, {}), InputError);
  EXPECT_THROW(search.run(top_uv, {{inner[0]}}, {.sweeps = -1}), InputError);
  EXPECT_THROW(search.run(top_uv, {{inner[0]}}, {.min_volume_ratio = 1.0f}), InputError);
  EXPECT_THROW(search.run(top_uv, {{inner[0]}}, {.min_volume_ratio = -0.1f}), InputError);
  std::vector<glm::vec2> short_uv(top_uv.begin(), top_uv.end() - 1);
  EXPECT_THROW(search.run(short_uv, {{inner[0]}}, {}), InputError);
  // A device that cuts long loops (lavapipe) refuses searches that would run past its budget.
  if (const uint32_t budget = device().max_loop_iterations()) {
    EXPECT_THROW(search.run(top_uv, {{inner[0]}}, {.golden_steps = budget}), InputError);
  }
  top_uv[inner[1]].y = NAN;
  EXPECT_THROW(search.run(top_uv, {{inner[0]}}, {}), InputError);
}

MESHQUILT_ON_BACKENDS(StretchLineSearch);

// Vulkan against its C++ twin: they differ only by rounding (cos, sin, fused multiply-adds), but
// a line minimum found in float32 is fixed only to about sqrt(float epsilon) of the local scale
// (energies closer than their rounding compare either way), so positions differ by up to about
// 5e-4 of an edge on a unit grid. A finer grid over the same 6 units keeps that inside 1e-4 of
// the grid's size (3e-4 against 6e-4 on lavapipe).
TEST_F(StretchLineSearch, VulkanAgreesWithCpuTwin) {
  std::string why;
  meshquilt::engine::Device* vulkan = shared_device(Backend::vulkan, &why);
  MESHQUILT_REQUIRE_DEVICE(vulkan, why);
  const double size = 6.0;
  const ShellMap map = bumpy_grid(21, size / 20);
  const Colours colours = greedy_colours(map.problem, interior(map));
  const StretchSearchOptions options{.sweeps = 20, .seed = 0x1234'5678'9abcULL};
  std::vector<glm::vec2> on_gpu = map.top_uv, on_cpu = map.top_uv;
  Search(*vulkan, map.problem).run(on_gpu, colours, options);
  Search(*shared_device(Backend::cpu, &why), map.problem).run(on_cpu, colours, options);
  for (uint32_t a = 0; a < on_cpu.size(); ++a) {
    EXPECT_NEAR(on_gpu[a].x, on_cpu[a].x, 1e-4 * size) << a;
    EXPECT_NEAR(on_gpu[a].y, on_cpu[a].y, 1e-4 * size) << a;
  }
  const double cpu_energy = total_energy(map.problem, on_cpu);
  EXPECT_NEAR(total_energy(map.problem, on_gpu), cpu_energy, 1e-4 * cpu_energy);
  EXPECT_LT(cpu_energy, 0.98 * total_energy(map.problem, map.top_uv));
}

TEST_F(StretchLineSearch, SameSeedSameResult) {
  std::string why;
  meshquilt::engine::Device& cpu = *shared_device(Backend::cpu, &why);
  const ShellMap map = bumpy_grid();
  const Colours colours = greedy_colours(map.problem, interior(map));
  const auto run = [&](uint64_t seed) {
    std::vector<glm::vec2> top_uv = map.top_uv;
    Search(cpu, map.problem).run(top_uv, colours, {.sweeps = 8, .seed = seed});
    return top_uv;
  };
  const std::vector<glm::vec2> first = run(7);
  EXPECT_EQ(run(7), first);  // bit for bit
  const std::vector<glm::vec2> other = run(8);
  std::size_t differ = 0;
  for (uint32_t a = 0; a < first.size(); ++a) differ += other[a] != first[a];
  EXPECT_GT(differ, interior(map).size() / 2);
  // The seed's high word counts too.
  const std::vector<glm::vec2> high = run(7 + (uint64_t{1} << 32));
  EXPECT_NE(high, first);
}

}  // namespace
