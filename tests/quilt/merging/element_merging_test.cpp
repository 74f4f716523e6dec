// merge_elements on the paper's cases: tubes crossing an overlap band (weave yarn), coincident
// rings (chain mail), wholly-inside elements, and pairs that cannot be stitched.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <random>

#include "merging_fixtures.h"
#include "mesh/mesh_io.h"
#include "quilt/merging/element_merging.h"

namespace meshquilt {
namespace {

void expect_closed_single_component(const TriMesh& m, long euler) {
  const test::Topology t = test::topology(m);
  EXPECT_TRUE(t.no_repeated_index);
  EXPECT_TRUE(t.every_edge_twice_opposite);
  EXPECT_TRUE(t.vertex_links_are_cycles);
  EXPECT_EQ(t.euler, euler);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.unused_vertices, 0);
  EXPECT_GT(test::signed_volume(m), 0.0);
  std::pair<int, int> first{-1, -1};
  EXPECT_EQ(test::crossing_pairs(m, &first), 0);
  if (first.first >= 0)
    for (int f : {first.first, first.second}) {
      const Tri& t = m.triangles[f];
      for (int k = 0; k < 3; ++k)
        std::printf("face %d v%d (%.4f %.4f %.4f)\n", f, t[k], m.positions[t[k]].x, m.positions[t[k]].y, m.positions[t[k]].z);
    }
}

double distance_to_vertices(const Vec3& p, const TriMesh& m) {
  double d = 1e300;
  for (const Vec3& q : m.positions) d = std::min(d, glm::length(p - q));
  return d;
}

TEST(ElementMerging, TubesAcrossABandStitchIntoOneClosedTube) {
  // Output yarn from the left, input yarn to the right, both present in the band |x| < 0.6.
  const TriMesh out = test::capped_tube(-1.5, 0.5, 0.25, 21, 16);
  TriMesh in = test::capped_tube(-0.5, 1.5, 0.25, 23, 13, 0.2, Vec3(0.0, 0.02, -0.01));
  test::rotate_z(in, 0.01);
  const auto band = [](const Vec3& p) { return std::abs(p.x) < 0.6; };
  const auto t0 = std::chrono::steady_clock::now();
  const MergeResult r = merge_elements(out, in, band);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("tube merge: %.2f ms, %zu faces\n", ms, r.element.num_faces());
  ASSERT_EQ(r.outcome, MergeOutcome::stitched) << r.fallback;
  EXPECT_EQ(r.seam_loops, 1);
  expect_closed_single_component(r.element, 2);
  // Spans the union of both extents.
  double lo = 1e9, hi = -1e9;
  for (const Vec3& p : r.element.positions) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
  EXPECT_NEAR(lo, -1.5, 0.02);
  EXPECT_NEAR(hi, in.positions.back().x, 0.02);
  // Stays on the inputs: every vertex near one of them; far parts barely move.
  for (const Vec3& p : r.element.positions)
    EXPECT_LT(std::min(distance_to_vertices(p, out), distance_to_vertices(p, in)), 0.15);
  for (const Vec3& p : out.positions)
    if (p.x < -1.0) {
      EXPECT_LT(distance_to_vertices(p, r.element), 1e-3);
    }
}

TEST(ElementMerging, CoincidentRingsStitchIntoOneClosedTorus) {
  // Chain-mail case: the same ring, tessellated differently, half of it over the overlap.
  const TriMesh out = test::torus(1.0, 0.25, 48, 12);
  const TriMesh in = test::torus(1.0, 0.25, 40, 10, 0.05, 0.2);
  const auto half = [](const Vec3& p) { return p.x > 0.0; };
  const MergeResult r = merge_elements(out, in, half);
  ASSERT_EQ(r.outcome, MergeOutcome::stitched) << r.fallback;
  EXPECT_EQ(r.seam_loops, 2);
  expect_closed_single_component(r.element, 0);
  // Away from the seams, the output half (x < 0) is the output's tessellation and the overlap
  // half the input's (the two tessellations' vertices lie an edge apart, so this tells them apart).
  int from_out = 0, from_in = 0;
  for (const Vec3& p : r.element.positions) {
    if (p.x < -0.85) {
      EXPECT_LT(distance_to_vertices(p, out), 1e-3);
      ++from_out;
    }
    if (p.x > 0.85) {
      EXPECT_LT(distance_to_vertices(p, in), 1e-3);
      ++from_in;
    }
  }
  EXPECT_GT(from_out, 50);
  EXPECT_GT(from_in, 50);
}

TEST(ElementMerging, WhollyInsideElementsYield) {
  const TriMesh out = test::capped_tube(-1.5, 0.5, 0.25, 21, 16);
  const TriMesh in = test::capped_tube(-0.5, 1.5, 0.25, 23, 13, 0.2);
  const MergeResult all = merge_elements(out, in, [](const Vec3&) { return true; });
  EXPECT_EQ(all.outcome, MergeOutcome::kept_in);
  EXPECT_EQ(all.element.triangles, in.triangles);
  // Overlap covering the input (x > -0.7) but not the whole output.
  const MergeResult covered = merge_elements(out, in, [](const Vec3& p) { return p.x > -0.7; });
  EXPECT_EQ(covered.outcome, MergeOutcome::kept_out);
  EXPECT_EQ(covered.element.triangles, out.triangles);
  EXPECT_EQ(covered.element.positions, out.positions);
  // Overlap covering the output (x < 0.7) but not the whole input.
  const MergeResult replaced = merge_elements(out, in, [](const Vec3& p) { return p.x < 0.7; });
  EXPECT_EQ(replaced.outcome, MergeOutcome::kept_in);
  EXPECT_EQ(replaced.element.positions, in.positions);
}

TEST(ElementMerging, UnstitchablePairKeepsTheMoreCompleteElementWhole) {
  // The input is two parallel yarns; only one continues the output's yarn. A stitch would leave
  // two components, so the element with more faces outside the overlap survives unchanged.
  const TriMesh out = test::capped_tube(-1.5, 0.5, 0.25, 21, 16);
  const TriMesh in = test::concat(test::capped_tube(-0.5, 1.5, 0.25, 23, 13, 0.2),
                                  test::capped_tube(-0.5, 1.5, 0.25, 23, 13, 0.2, Vec3(0.0, 0.9, 0.0)));
  const auto band = [](const Vec3& p) { return std::abs(p.x) < 0.6; };
  const MergeResult r = merge_elements(out, in, band);
  EXPECT_FALSE(r.fallback.empty());
  ASSERT_EQ(r.outcome, MergeOutcome::kept_in) << r.fallback;  // two yarns outside vs one
  EXPECT_EQ(r.element.positions, in.positions);
  EXPECT_EQ(r.element.triangles, in.triangles);

  // A longer output now has more faces outside the overlap: it is kept whole instead.
  const TriMesh long_out = test::capped_tube(-4.5, 0.5, 0.25, 51, 16);
  const MergeResult r2 = merge_elements(long_out, in, band);
  ASSERT_EQ(r2.outcome, MergeOutcome::kept_out) << r2.fallback;
  EXPECT_EQ(r2.element.positions, long_out.positions);
  EXPECT_EQ(r2.element.triangles, long_out.triangles);
}

// Random misalignments, tessellations and bands: every outcome must be a clean closed element
// (stitched) or one input whole (fallback), never a broken one; most must stitch.
TEST(ElementMerging, RandomTubePairsAlwaysYieldAClosedElement) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int stitched = 0, trials = 24;
  double worst_ms = 0.0;
  for (int trial = 0; trial < trials; ++trial) {
    const double band = 0.45 + 0.3 * u(rng);
    const double out_end = band * (0.5 + 0.45 * u(rng)), in_start = -band * (0.5 + 0.45 * u(rng));
    const TriMesh out = test::capped_tube(-1.5, out_end, 0.25, 16 + static_cast<int>(12 * u(rng)), 10 + static_cast<int>(8 * u(rng)), u(rng));
    TriMesh in = test::capped_tube(in_start, 1.5, 0.25, 16 + static_cast<int>(12 * u(rng)), 10 + static_cast<int>(8 * u(rng)), u(rng),
                                   Vec3(0.0, 0.04 * (u(rng) - 0.5), 0.04 * (u(rng) - 0.5)));
    test::rotate_z(in, 0.03 * (u(rng) - 0.5));
    const auto overlap = [band](const Vec3& p) { return std::abs(p.x) < band; };
    const auto t0 = std::chrono::steady_clock::now();
    const MergeResult r = merge_elements(out, in, overlap);
    worst_ms = std::max(worst_ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + r.fallback);
    if (r.outcome == MergeOutcome::stitched) {
      ++stitched;
      const test::Topology t = test::topology(r.element);
      EXPECT_TRUE(t.every_edge_twice_opposite && t.vertex_links_are_cycles && t.no_repeated_index);
      EXPECT_EQ(t.euler, 2);
      EXPECT_EQ(t.components, 1);
      EXPECT_EQ(test::crossing_pairs(r.element), 0);
    } else {
      const TriMesh& whole = r.outcome == MergeOutcome::kept_in ? in : out;
      EXPECT_EQ(r.element.triangles, whole.triangles);
      EXPECT_EQ(r.element.positions, whole.positions);
      std::printf("trial %d fell back: %s\n", trial, r.fallback.c_str());
    }
  }
  std::printf("random tubes: %d of %d stitched, slowest merge %.1f ms\n", stitched, trials, worst_ms);
  EXPECT_GE(stitched, trials * 9 / 10);
}

TEST(ElementMerging, RandomRingPairsAlwaysYieldAClosedElement) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int stitched = 0, trials = 16;
  for (int trial = 0; trial < trials; ++trial) {
    const TriMesh out = test::torus(1.0, 0.25, 30 + static_cast<int>(24 * u(rng)), 8 + static_cast<int>(8 * u(rng)), u(rng), u(rng));
    TriMesh in = test::torus(1.0, 0.25, 30 + static_cast<int>(24 * u(rng)), 8 + static_cast<int>(8 * u(rng)), u(rng), u(rng));
    for (Vec3& p : in.positions) p += Vec3(0.03 * (u(rng) - 0.5), 0.03 * (u(rng) - 0.5), 0.0) * 0.0 + Vec3(0.01, -0.01, 0.005);
    const double angle = 2.0 * M_PI * u(rng), offset = 0.4 * (u(rng) - 0.5);
    const Vec3 dir(std::cos(angle), std::sin(angle), 0.0);
    const auto overlap = [dir, offset](const Vec3& p) { return glm::dot(p, dir) > offset; };
    const MergeResult r = merge_elements(out, in, overlap);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + r.fallback);
    if (r.outcome == MergeOutcome::stitched) {
      ++stitched;
      const test::Topology t = test::topology(r.element);
      EXPECT_TRUE(t.every_edge_twice_opposite && t.vertex_links_are_cycles && t.no_repeated_index);
      EXPECT_EQ(t.euler, 0);
      EXPECT_EQ(t.components, 1);
      EXPECT_EQ(test::crossing_pairs(r.element), 0);
    } else {
      const TriMesh& whole = r.outcome == MergeOutcome::kept_in ? in : out;
      EXPECT_EQ(r.element.triangles, whole.triangles);
      std::printf("ring trial %d fell back: %s\n", trial, r.fallback.c_str());
    }
  }
  std::printf("random rings: %d of %d stitched\n", stitched, trials);
  EXPECT_GE(stitched, trials * 3 / 4);
}

// Weave yarns: undulating tubes, larger misalignments, coarse and fine tessellations.
TEST(ElementMerging, RandomYarnPairsAlwaysYieldAClosedElement) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int stitched = 0, trials = 16;
  for (int trial = 0; trial < trials; ++trial) {
    const double band = 0.5 + 0.3 * u(rng), amplitude = 0.3 * u(rng), wavelength = 1.5 + u(rng);
    const double radius = 0.12 + 0.1 * u(rng);
    const TriMesh out = test::swept_tube(test::yarn_centre(-2.0, band * 0.8, 24 + static_cast<int>(20 * u(rng)), amplitude, wavelength),
                                         radius, 6 + static_cast<int>(12 * u(rng)), u(rng));
    const Vec3 shift(0.0, 0.3 * radius * (u(rng) - 0.5), 0.3 * radius * (u(rng) - 0.5));
    const TriMesh in = test::swept_tube(test::yarn_centre(-band * 0.8, 2.0, 24 + static_cast<int>(20 * u(rng)), amplitude, wavelength, shift),
                                        radius, 6 + static_cast<int>(12 * u(rng)), u(rng));
    ASSERT_GT(test::signed_volume(out), 0.0);
    const auto overlap = [band](const Vec3& p) { return std::abs(p.x) < band; };
    const MergeResult r = merge_elements(out, in, overlap);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + r.fallback);
    if (r.outcome == MergeOutcome::stitched) {
      ++stitched;
      const test::Topology t = test::topology(r.element);
      EXPECT_TRUE(t.every_edge_twice_opposite && t.vertex_links_are_cycles && t.no_repeated_index);
      EXPECT_EQ(t.euler, 2);
      EXPECT_EQ(t.components, 1);
      EXPECT_EQ(test::crossing_pairs(r.element), 0);
      EXPECT_GT(test::signed_volume(r.element), 0.0);
    } else {
      const TriMesh& whole = r.outcome == MergeOutcome::kept_in ? in : out;
      EXPECT_EQ(r.element.triangles, whole.triangles);
      std::printf("yarn trial %d fell back: %s\n", trial, r.fallback.c_str());
    }
  }
  std::printf("random yarns: %d of %d stitched\n", stitched, trials);
  EXPECT_GE(stitched, trials * 3 / 4);
}

// A real closed tube (CGAL's torus knot, genus 1) against a misaligned copy of itself, cut by
// planes that cross it two or three times.
TEST(ElementMerging, RealKnotStitchesAcrossEveryCrossing) {
  const std::filesystem::path file = std::filesystem::path(MESHQUILT_SHARED_DIR) / "data/meshes/knot.off";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not available";
  const TriMesh out = read_mesh(file);
  ASSERT_EQ(test::topology(out).euler, 0);
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : out.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const Vec3 centre = 0.5 * (lo + hi);
  for (double plane : {0.0, 0.2, -0.3}) {
    TriMesh in = out;
    test::rotate_z(in, 0.02, centre);
    for (Vec3& p : in.positions) p += Vec3(0.003, -0.002, 0.002) * glm::length(hi - lo);
    const double cut = centre.x + plane * 0.5 * (hi.x - lo.x);
    const MergeResult r = merge_elements(out, in, [cut](const Vec3& p) { return p.x > cut; });
    SCOPED_TRACE("plane " + std::to_string(plane) + ": " + r.fallback);
    ASSERT_EQ(r.outcome, MergeOutcome::stitched);
    EXPECT_GE(r.seam_loops, 2);
    expect_closed_single_component(r.element, 0);
  }
}

}  // namespace
}  // namespace meshquilt
