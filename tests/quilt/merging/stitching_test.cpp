// Stitching of cut parts: loops, pairing, alignment, welding, refusal.
#include <gtest/gtest.h>

#include <algorithm>

#include "merging_fixtures.h"
#include "mesh/measures.h"
#include "mesh/topology.h"
#include "quilt/merging/stitching.h"

namespace meshquilt {
namespace {

std::vector<uint8_t> keep_where(const TriMesh& m, bool (*pred)(const Vec3&)) {
  std::vector<uint8_t> keep(m.num_faces());
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const Tri& t = m.triangles[f];
    keep[f] = pred((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0);
  }
  return keep;
}

TEST(Stitching, FixturesAreClosedOutwardSurfaces) {
  const TriMesh tube = test::capped_tube(-1, 1, 0.25, 11, 12);
  const test::Topology t = test::topology(tube);
  EXPECT_TRUE(t.every_edge_twice_opposite);
  EXPECT_TRUE(t.vertex_links_are_cycles);
  EXPECT_EQ(t.euler, 2);
  EXPECT_GT(test::signed_volume(tube), 0.0);
  const TriMesh ring = test::torus(1.0, 0.25, 24, 10);
  EXPECT_EQ(test::topology(ring).euler, 0);
  EXPECT_GT(test::signed_volume(ring), 0.0);
  const SurfaceReport r = inspect_surface(tube);
  EXPECT_TRUE(r.closed_manifold());
  EXPECT_EQ(r.euler, 2);
  EXPECT_EQ(r.components, 1);
}

TEST(Stitching, CutLoopsOfAHalfTubeIsOneRingLeftOfTheKeptPart) {
  const TriMesh tube = test::capped_tube(-1, 1, 0.25, 11, 12);  // rings at x = -1, -0.8, ..., 1
  const auto keep = keep_where(tube, [](const Vec3& c) { return c.x < 0.0; });
  std::vector<CutLoop> loops;
  ASSERT_TRUE(cut_loops(tube, face_neighbors(tube), keep, loops));
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].vertices.size(), 12u);
  for (int32_t v : loops[0].vertices) EXPECT_NEAR(tube.positions[v].x, 0.0, 1e-12);
  // Kept faces (x < 0) lie to the left: seen from +x (outside the kept part) the loop turns
  // clockwise, i.e. its winding about +x is negative.
  double winding = 0.0;
  for (size_t k = 0; k < 12; ++k) {
    const Vec3 a = tube.positions[loops[0].vertices[k]], b = tube.positions[loops[0].vertices[(k + 1) % 12]];
    winding += a.y * b.z - a.z * b.y;
  }
  EXPECT_LT(winding, 0.0);
  for (size_t k = 0; k < 12; ++k) EXPECT_TRUE(keep[loops[0].faces[k]]);
}

TEST(Stitching, TidyRemovesEarsAndPinches) {
  const TriMesh tube = test::capped_tube(-1, 1, 0.25, 11, 12);
  auto keep = keep_where(tube, [](const Vec3& c) { return c.x < 0.0; });
  const auto nb = face_neighbors(tube);
  // Add one face of the next ring band: an ear with two cut edges.
  size_t ear = 0;
  for (size_t f = 0; f < tube.num_faces(); ++f)
    if (!keep[f]) {
      int kept_nb = 0;
      for (int32_t g : nb[f]) kept_nb += g >= 0 && keep[g];
      if (kept_nb == 1) {
        ear = f;
        break;
      }
    }
  keep[ear] = 1;
  EXPECT_GE(tidy_cut(tube, nb, keep), 1);
  EXPECT_EQ(keep[ear], 0);
  std::vector<CutLoop> loops;
  EXPECT_TRUE(cut_loops(tube, nb, keep, loops));
  EXPECT_EQ(loops.size(), 1u);
}

TEST(Stitching, ComplementaryHalvesOfOneMeshWeldBackExactly) {
  const TriMesh tube = test::capped_tube(-1, 1, 0.25, 11, 12);
  const auto keep_a = keep_where(tube, [](const Vec3& c) { return c.x < 0.0; });
  std::vector<uint8_t> keep_b(keep_a.size());
  for (size_t f = 0; f < keep_a.size(); ++f) keep_b[f] = !keep_a[f];
  const StitchResult r = stitch_parts(tube, keep_a, tube, keep_b);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.loop_pairs, 1);
  EXPECT_EQ(r.mesh.num_faces(), tube.num_faces());
  EXPECT_EQ(r.mesh.num_vertices(), tube.num_vertices());
  const test::Topology t = test::topology(r.mesh);
  EXPECT_TRUE(t.every_edge_twice_opposite);
  EXPECT_EQ(t.euler, 2);
  EXPECT_EQ(t.components, 1);
  // The seam points were already at their averages: nothing moves.
  double max_move = 0.0;
  for (const Vec3& p : r.mesh.positions) {
    double d = 1e9;
    for (const Vec3& q : tube.positions) d = std::min(d, glm::length(p - q));
    max_move = std::max(max_move, d);
  }
  EXPECT_LT(max_move, 1e-9);
}

TEST(Stitching, DifferentTessellationsWeldIntoOneClosedSurface) {
  // a: 16 sides, rings every 0.1; b: 11 sides, rotated, rings every 0.125, slightly offset.
  const TriMesh a = test::capped_tube(-1, 1, 0.25, 21, 16);
  const TriMesh b = test::capped_tube(-1, 1, 0.25, 17, 11, 0.3, Vec3(0.0, 0.01, -0.005));
  const auto keep_a = keep_where(a, [](const Vec3& c) { return c.x < 0.02; });
  const auto keep_b = keep_where(b, [](const Vec3& c) { return c.x > 0.0; });
  const StitchResult r = stitch_parts(a, keep_a, b, keep_b);
  ASSERT_TRUE(r.ok) << r.failure;
  const test::Topology t = test::topology(r.mesh);
  EXPECT_TRUE(t.no_repeated_index);
  EXPECT_TRUE(t.every_edge_twice_opposite);
  EXPECT_TRUE(t.vertex_links_are_cycles);
  EXPECT_EQ(t.euler, 2);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.unused_vertices, 0);
  EXPECT_GT(test::signed_volume(r.mesh), 0.0);
  EXPECT_EQ(test::crossing_pairs(r.mesh), 0);
  // Every seam triangle has a real area.
  for (const Tri& f : r.mesh.triangles) {
    const Vec3 &p = r.mesh.positions[f[0]], &q = r.mesh.positions[f[1]], &s = r.mesh.positions[f[2]];
    EXPECT_GT(glm::length(glm::cross(q - p, s - p)), 1e-6);
  }
}

TEST(Stitching, RefusesTwoLoopsAgainstOne) {
  const TriMesh a = test::capped_tube(-1, 1, 0.25, 21, 16);
  const TriMesh b = test::capped_tube(-1, 1, 0.25, 17, 11, 0.3);
  const auto keep_a = keep_where(a, [](const Vec3& c) { return c.x < 0.0; });                        // one loop
  const auto keep_b = keep_where(b, [](const Vec3& c) { return c.x > 0.5 || c.x < -0.5; });          // two loops
  const StitchResult r = stitch_parts(a, keep_a, b, keep_b);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("cut loops"), std::string::npos) << r.failure;
}

TEST(Stitching, RefusesOppositelyOrientedParts) {
  const TriMesh a = test::capped_tube(-1, 1, 0.25, 21, 16);
  TriMesh b = test::capped_tube(-1, 1, 0.25, 17, 11, 0.3);
  for (Tri& t : b.triangles) std::swap(t[1], t[2]);  // inward-facing
  const auto keep_a = keep_where(a, [](const Vec3& c) { return c.x < 0.0; });
  const auto keep_b = keep_where(b, [](const Vec3& c) { return c.x > 0.0; });
  const StitchResult r = stitch_parts(a, keep_a, b, keep_b);
  EXPECT_FALSE(r.ok);
}

}  // namespace
}  // namespace meshquilt
