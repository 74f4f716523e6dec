// Coverage, heights and element statistics of the inspect report: exact constructed cases and
// independent brute-force references.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <random>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/error.h"
#include "inspect/coverage.h"
#include "inspect/element_statistics.h"
#include "inspect/inspect_report.h"
#include "mesh/mesh_io.h"

namespace meshquilt {
namespace {

const Vec3 X(1, 0, 0), Y(0, 1, 0);

// Ring in the x-y plane (nv a multiple of 4, so vertices reach exactly z = center.z +- r).
void add_ring(TriMesh& m, const Vec3& center, double R, double r, int nu = 24, int nv = 8) {
  const auto base = static_cast<int32_t>(m.positions.size());
  for (int i = 0; i < nu; ++i) {
    const double u = 2.0 * std::numbers::pi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2.0 * std::numbers::pi * j / nv;
      const double s = j % (nv / 4) == 0 ? std::round(std::sin(v)) : std::sin(v);
      m.positions.push_back(center + (R + r * std::cos(v)) * (std::cos(u) * X + std::sin(u) * Y) + Vec3(0, 0, r * s));
    }
  }
  auto id = [&](int i, int j) { return base + ((i + nu) % nu) * nv + (j + nv) % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
}

// A flat square [0, size]^2 at z = 0, n x n quads.
TriMesh square(double size, int n) {
  TriMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.emplace_back(size * i / n, size * j / n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

TEST(KsDistance, ExactValues) {
  EXPECT_DOUBLE_EQ(ks_distance({1, 2, 3}, {3, 2, 1}), 0.0);
  EXPECT_DOUBLE_EQ(ks_distance({1, 2}, {3, 4}), 1.0);
  EXPECT_DOUBLE_EQ(ks_distance({1, 2, 3, 4}, {3, 4, 5, 6}), 0.5);
  // Ties across samples: F_a(1) = 1/2, F_b(1) = 1/4, then both reach 1 at 2... largest gap 1/4
  // at x = 1 and 1/4 at x = 2 (F_a = 1, F_b = 3/4).
  EXPECT_DOUBLE_EQ(ks_distance({1, 2}, {1, 2, 2, 3}), 0.25);
  EXPECT_TRUE(std::isnan(ks_distance({}, {1.0})));
  // Rounding noise is a tie, not a difference; a real difference is not.
  EXPECT_DOUBLE_EQ(ks_distance({1.0, 2.0}, {1.0 + 1e-14, 2.0 - 1e-14}), 0.0);
  EXPECT_DOUBLE_EQ(ks_distance({1.0, 2.0}, {1.0 + 1e-6, 2.0 + 1e-6}), 0.5);
}

TEST(ElementMeasures, SquareAndRing) {
  TriMesh m = square(2.0, 3);
  m.elements.assign(m.num_faces(), 0);
  const ElementMeasures e = element_measures(m, m.elements, 1);
  EXPECT_NEAR(e.area[0], 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(e.extent[0], 2.0);
  EXPECT_DOUBLE_EQ(e.xy_extent[0], 2.0);
  EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 2.0, 3.0}), 2.5);
}

TEST(Inspect, SwatchKsIsZeroForTheSameRingsElsewhere) {
  // The same rings at other positions: areas equal up to rounding, so the distance is 0.
  TriMesh swatch, out;
  for (int i = 0; i < 3; ++i) add_ring(swatch, {3.0 * i, 0, 0}, 0.5, 0.1);
  for (int i = 0; i < 40; ++i) add_ring(out, {3.0 * (i % 8) + 0.1 * i, 3.7 * (i / 8), 0.3}, 0.5, 0.1);
  const InspectReport r = inspect_mesh(out, {}, &swatch);
  EXPECT_DOUBLE_EQ(r.swatch->element_area_ks, 0.0);
  EXPECT_DOUBLE_EQ(r.swatch->element_extent_ks, 0.0);
}

TEST(Inspect, SwatchKsIsZeroAgainstItselfAndOneAgainstBiggerElements) {
  TriMesh small, big;
  for (int i = 0; i < 4; ++i) add_ring(small, {3.0 * i, 0, 0}, 0.5, 0.1);
  for (int i = 0; i < 4; ++i) add_ring(big, {6.0 * i, 0, 0}, 1.0, 0.2);
  const InspectReport same = inspect_mesh(small, {}, &small);
  ASSERT_TRUE(same.swatch);
  EXPECT_EQ(same.swatch->elements, 4);
  EXPECT_DOUBLE_EQ(same.swatch->element_area_ks, 0.0);
  EXPECT_DOUBLE_EQ(same.swatch->element_extent_ks, 0.0);
  const InspectReport other = inspect_mesh(small, {}, &big);
  EXPECT_DOUBLE_EQ(other.swatch->element_area_ks, 1.0);
  EXPECT_DOUBLE_EQ(other.swatch->element_extent_ks, 1.0);
}

// Rings of x-y extent 1.1 on a 16 x 16 grid of pitch 1.2; `keep` chooses which.
TriMesh ring_field(const std::function<bool(int, int)>& keep, double z = 0.0) {
  TriMesh m;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i)
      if (keep(i, j)) add_ring(m, {0.6 + 1.25 * i, 0.6 + 1.25 * j, z}, 0.4, 0.15);
  return m;
}

TEST(PlaneCoverage, FullAndHalfCoveredPlane) {
  InspectOptions options;
  options.plane = true;
  const InspectReport full = inspect_mesh(ring_field([](int, int) { return true; }), options);
  ASSERT_TRUE(full.plane);
  EXPECT_NEAR(full.plane->cell_size, 0.55, 1e-9);  // half the ring's x-y extent
  EXPECT_GT(full.plane->coverage, 0.99);           // ring holes (0.5 across) are no gaps
  // The left half, plus one ring in the far corner so the footprint stays the same.
  const InspectReport half = inspect_mesh(ring_field([](int i, int j) { return i < 8 || (i == 15 && j == 15); }), options);
  EXPECT_NEAR(half.plane->coverage, 0.5, 0.05);
  EXPECT_GT(half.plane->largest_gap, 0.4);
  EXPECT_LT(half.plane->largest_gap, 0.5);
}

// A flat rectangle [x0, x1] x [y0, y1] at z = 0, as two triangles.
void add_rectangle(TriMesh& m, double x0, double y0, double x1, double y1) {
  const auto b = static_cast<int32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {{x0, y0, 0.0}, {x1, y0, 0.0}, {x1, y1, 0.0}, {x0, y1, 0.0}});
  m.triangles.push_back({b, b + 1, b + 2});
  m.triangles.push_back({b, b + 2, b + 3});
}

TEST(LargestEmptySquare, GapBetweenTwoBarsAndHoleOfAFrame) {
  // Two bars 1 apart, 6 tall: the largest free square is 1 across; the raster rounds up by at
  // most three of its pixels (6 / 512 each), never down.
  TriMesh bars;
  add_rectangle(bars, 0.0, 0.0, 2.0, 6.0);
  add_rectangle(bars, 3.0, 0.0, 5.0, 6.0);
  const double pixel = 6.0 / 512;
  EXPECT_GE(largest_empty_square(bars), 1.0);
  EXPECT_LE(largest_empty_square(bars), 1.0 + 3.0 * pixel);
  // A square frame of side 10 round a hole of side 6.
  TriMesh frame;
  add_rectangle(frame, 0.0, 0.0, 10.0, 2.0);
  add_rectangle(frame, 0.0, 8.0, 10.0, 10.0);
  add_rectangle(frame, 0.0, 2.0, 2.0, 8.0);
  add_rectangle(frame, 8.0, 2.0, 10.0, 8.0);
  EXPECT_GE(largest_empty_square(frame), 6.0);
  EXPECT_LE(largest_empty_square(frame), 6.0 + 3.0 * 10.0 / 512);
  // A sheet has no free pixel: two pixels, so that any gap between copies of it shows.
  TriMesh sheet;
  add_rectangle(sheet, 0.0, 0.0, 4.0, 2.0);
  EXPECT_DOUBLE_EQ(largest_empty_square(sheet), 2.0 * 4.0 / 512);
  EXPECT_EQ(largest_empty_square(TriMesh{}), 0.0);
}

TEST(LargestEmptySquare, LeavesOutTheCornersOfATurnedLayout) {
  // Squares 0.5 across at pitch 1 filling a diamond |x| + |y| <= 5: inside its outline the free
  // squares are 0.5 across, while each corner of its bounding box is a free triangle with legs
  // of 5 that would hold a square of 2.5.
  TriMesh diamond;
  for (int j = -5; j <= 5; ++j)
    for (int i = -5; i <= 5; ++i)
      if (std::abs(i) + std::abs(j) <= 5) add_rectangle(diamond, i - 0.25, j - 0.25, i + 0.25, j + 0.25);
  const double side = largest_empty_square(diamond);
  EXPECT_GE(side, 0.5);
  EXPECT_LE(side, 0.5 + 3.0 * 10.5 / 512);
}

// A sparse swatch's own holes are not missing cover: rings far apart (holes 1.4 across, gaps of
// 2 between rings) quilted as themselves cover their plane, and a missing ring is a gap.
TEST(PlaneCoverage, CellsFromTheSwatchsLargestGap) {
  const auto rings = [](int skip) {
    TriMesh m;
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i)
        if (j * 6 + i != skip) add_ring(m, {4.0 * i, 4.0 * j, 0.0}, 1.0, 0.3, 32, 8);
    return m;
  };
  const TriMesh swatch = rings(-1);
  InspectOptions options;
  options.plane = true;
  // Half the median ring (1.3 across) fits inside the gaps between rings: coverage well below 1.
  EXPECT_LT(inspect_mesh(swatch, options).plane->coverage, 0.9);
  const InspectReport self = inspect_mesh(swatch, options, &swatch);
  EXPECT_NEAR(self.plane->cell_size, largest_empty_square(swatch), 1e-12);
  EXPECT_EQ(self.plane->coverage, 1.0);
  // One ring of 36 in the middle missing: its place is a gap at the swatch's cells.
  const InspectReport missing = inspect_mesh(rings(14), options, &swatch);
  EXPECT_LT(missing.plane->coverage, 0.99);
  EXPECT_GT(missing.plane->largest_gap, 0.0);
}

// A region replaces the footprint: the same rings measured over the plane they were meant to
// cover, twice as wide as they are, and over a region inside them.
TEST(PlaneCoverage, RegionReplacesTheFootprint) {
  const TriMesh rings = ring_field([](int, int) { return true; });  // x-y from 0.05 to 19.85
  PlaneCoverageOptions options;
  options.region = {glm::dvec2(0.05), glm::dvec2(0.05 + 2 * 19.8, 19.85)};
  const PlaneCoverage wide = plane_coverage(rings, 0.55, options);
  EXPECT_EQ(wide.cells_x, 72);  // 39.6 / 0.55
  EXPECT_EQ(wide.cells_y, 36);
  EXPECT_NEAR(wide.coverage, 0.5, 0.02);  // the rings' half, and the column touching its edge
  options.region = {glm::dvec2(5.0), glm::dvec2(10.0)};
  EXPECT_GT(plane_coverage(rings, 0.55, options).coverage, 0.99);
  options.region = {glm::dvec2(5.0), glm::dvec2(5.0, 10.0)};
  EXPECT_THROW(plane_coverage(rings, 0.55, options), InputError);
}

// Reference overlap of a triangle's x-y projection with a box, without separating axes: a
// vertex of one inside the other, or crossing edges.
bool ref_overlap(const glm::dvec2 t[3], double x0, double y0, double x1, double y1) {
  auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  for (int k = 0; k < 3; ++k)
    if (t[k].x >= x0 && t[k].x <= x1 && t[k].y >= y0 && t[k].y <= y1) return true;
  const glm::dvec2 c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (const auto& p : c) {
    const double a = cross(t[0], t[1], p), b = cross(t[1], t[2], p), d = cross(t[2], t[0], p);
    if ((a >= 0 && b >= 0 && d >= 0) || (a <= 0 && b <= 0 && d <= 0)) return true;
  }
  for (int k = 0; k < 3; ++k)
    for (int e = 0; e < 4; ++e) {
      const glm::dvec2 p = t[k], q = t[(k + 1) % 3], r = c[e], s = c[(e + 1) % 4];
      if (cross(p, q, r) * cross(p, q, s) < 0 && cross(r, s, p) * cross(r, s, q) < 0) return true;
    }
  return false;
}

TEST(PlaneCoverage, MatchesBruteForceOnRandomTriangles) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> pos(0.0, 10.0), d(-0.7, 0.7);
  TriMesh m;
  for (int i = 0; i < 150; ++i) {
    const Vec3 c(pos(rng), pos(rng), 0.0);
    const auto b = static_cast<int32_t>(m.positions.size());
    for (int k = 0; k < 3; ++k) m.positions.push_back(c + Vec3(d(rng), d(rng), d(rng)));
    m.triangles.push_back({b, b + 1, b + 2});
  }
  const PlaneCoverage cov = plane_coverage(m, 0.37);
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const Vec3& p : m.positions) {
    lo = glm::min(lo, glm::dvec2(p));
    hi = glm::max(hi, glm::dvec2(p));
  }
  const glm::dvec2 size = hi - lo;
  lo += 0.02 * size;
  hi -= 0.02 * size;
  ASSERT_EQ(cov.cells_x, static_cast<int>(std::round((hi.x - lo.x) / 0.37)));
  const double cw = (hi.x - lo.x) / cov.cells_x, ch = (hi.y - lo.y) / cov.cells_y;
  int covered = 0;
  for (int y = 0; y < cov.cells_y; ++y)
    for (int x = 0; x < cov.cells_x; ++x) {
      bool hit = false;
      for (const Tri& t : m.triangles) {
        const glm::dvec2 p[3] = {glm::dvec2(m.positions[t[0]]), glm::dvec2(m.positions[t[1]]), glm::dvec2(m.positions[t[2]])};
        if (ref_overlap(p, lo.x + x * cw, lo.y + y * ch, lo.x + (x + 1) * cw, lo.y + (y + 1) * ch)) {
          hit = true;
          break;
        }
      }
      covered += hit;
    }
  EXPECT_GT(covered, 50);
  EXPECT_LT(covered, cov.cells_x * cov.cells_y);
  EXPECT_DOUBLE_EQ(cov.coverage, double(covered) / (cov.cells_x * cov.cells_y));
}

TEST(BaseCoverage, FullAndHalfCoveredBaseWithExactHeights) {
  const TriMesh base = square(20.0, 10);
  const double diagonal = 20.0 * std::sqrt(2.0);
  const TriMesh full = ring_field([](int, int) { return true; }, 0.25);
  InspectOptions options;
  const InspectReport r = inspect_mesh(full, options, nullptr, &base);
  ASSERT_TRUE(r.base);
  EXPECT_GT(r.base->coverage, 0.97);
  EXPECT_NEAR(r.base->height_min, 0.10 / diagonal, 1e-12);
  EXPECT_NEAR(r.base->height_max, 0.40 / diagonal, 1e-12);
  EXPECT_FALSE(r.base->outside_shell_vertices);

  TriMesh half = ring_field([](int i, int) { return i < 8; }, 0.25);
  add_ring(half, {15.0, 10.0, -0.5}, 0.4, 0.15);  // sunk below the base
  options.shell_height = 0.35 / diagonal;
  const InspectReport h = inspect_mesh(half, options, nullptr, &base);
  EXPECT_NEAR(h.base->coverage, 0.5, 0.06);
  EXPECT_NEAR(h.base->height_min, -0.65 / diagonal, 1e-12);
  int64_t outside = 0;
  for (const Vec3& p : half.positions) outside += p.z < 0.0 || p.z > 0.35 + 1e-9;
  ASSERT_TRUE(h.base->outside_shell_vertices);
  EXPECT_EQ(*h.base->outside_shell_vertices, outside);
  EXPECT_GT(outside, 16 * 8 * 24 / 4);
}

TEST(SignedHeights, MatchBruteForceAroundAClosedConvexMesh) {
  const auto file = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data" / "meshes" / "sphere.off";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "shared meshes not available";
  const TriMesh sphere = read_mesh(file);
  Vec3 lo(1e300), hi(-1e300), center(0.0);
  for (const Vec3& p : sphere.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  center = 0.5 * (lo + hi);
  const double diagonal = glm::length(hi - lo);
  // Outward orientation from the signed volume.
  double volume = 0.0;
  for (const Tri& t : sphere.triangles)
    volume += glm::dot(sphere.positions[t[0]] - center, glm::cross(sphere.positions[t[1]] - center, sphere.positions[t[2]] - center));
  const double outward = volume > 0 ? 1.0 : -1.0;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  std::vector<Vec3> points;
  for (int i = 0; i < 2000; ++i) points.push_back(center + Vec3(u(rng), u(rng), u(rng)) * (hi - lo));
  const std::vector<double> h = signed_heights(points, sphere);
  for (size_t i = 0; i < points.size(); ++i) {
    // Inside a convex mesh: behind every face plane. Distance: sampled brute force over faces
    // (edges and the interior by a dense barycentric grid, good to 1e-3 of the face size).
    bool inside = true;
    double best = 1e300;
    for (const Tri& t : sphere.triangles) {
      const Vec3 &a = sphere.positions[t[0]], &b = sphere.positions[t[1]], &c = sphere.positions[t[2]];
      inside &= outward * glm::dot(points[i] - a, glm::cross(b - a, c - a)) <= 0.0;
      // Distance to the plane when the projection is inside; else to the three edges.
      const Vec3 n = glm::normalize(glm::cross(b - a, c - a));
      const Vec3 q = points[i] - glm::dot(points[i] - a, n) * n;
      const bool in = glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                      glm::dot(glm::cross(a - c, q - c), n) >= 0;
      if (in) best = std::min(best, std::abs(glm::dot(points[i] - a, n)));
      const Vec3 v[3] = {a, b, c};
      for (int e = 0; e < 3; ++e) {
        const Vec3 d = v[(e + 1) % 3] - v[e];
        const double s = std::clamp(glm::dot(points[i] - v[e], d) / glm::dot(d, d), 0.0, 1.0);
        best = std::min(best, glm::length(points[i] - (v[e] + s * d)));
      }
    }
    EXPECT_NEAR(std::abs(h[i]), best / diagonal, 1e-12);
    if (best > 1e-9 * diagonal) {
      EXPECT_EQ(h[i] < 0, inside) << i;
    }
  }
}

}  // namespace
}  // namespace meshquilt
