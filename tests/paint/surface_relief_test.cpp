// Relief against closed forms: a constant height image raises every vertex by the same height
// along its normal; a hollow too tight for the height is clamped, and the result stays closed
// and free of self-intersections, where the unclamped one passes through itself; a base that
// crosses itself is reported, and no face turns over at a steep step.

#include <gtest/gtest.h>

#include <memory>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "mesh/topology.h"
#include "device.h"
#include "paint/surface_relief.h"
#include "spatial/intersecting_pairs.h"
#include "support/surface_fixtures.h"
#include "support/torus.h"
#include "surface/base_layout.h"
#include "surface/surface_types.h"

namespace meshquilt {
namespace {

// Relief's own figures; paint's back ends are compared in surface_paint_test.
engine::Device* cpu() {
  static const std::unique_ptr<engine::Device> device = engine::open_device(engine::BackendChoice::cpu);
  return device.get();
}

ColourImage grey(double value) {
  ColourImage image;
  image.width = image.height = 8;
  image.rgb.assign(64, glm::dvec3(value));
  return image;
}

size_t self_intersections(const TriMesh& mesh) {
  return intersecting_face_pairs(mesh, std::vector<int32_t>(mesh.num_faces(), 0), IntersectionScope::same_element)
      .size();
}

TEST(SurfaceRelief, AConstantImageRaisesEveryVertexAlongItsNormal) {
  const TriMesh sphere = test::icosphere(2);
  ReliefOptions options;
  options.paint.pixels_per_unit = 6.0;
  options.height = 0.1;
  const ReliefResult relief = relief_surface(sphere, grey(0.6), {}, options, *cpu());
  // The same refinement, measured independently: each vertex moves by 0.6 x 0.1 along the
  // base's smooth normal, its vertex normals interpolated by area over the base face that holds
  // the vertex (found by search, not by the split's face order).
  const TriMesh refined = split_faces(sphere, relief.levels);
  ASSERT_EQ(relief.mesh.num_vertices(), refined.num_vertices());
  EXPECT_EQ(relief.mesh.triangles, refined.triangles);
  const BaseSurface base(sphere);
  const double expected = 0.1 * std::round(0.6 * 255.0) / 255.0;
  EXPECT_EQ(relief.clamped, 0);
  for (size_t v = 0; v < refined.num_vertices(); ++v) {
    const Vec3& p = refined.positions[v];
    Vec3 normal(0.0);
    for (size_t f = 0; f < sphere.num_faces() && normal == Vec3(0.0); ++f) {
      const Tri& t = sphere.triangles[f];
      const Vec3 a = sphere.positions[t[0]], b = sphere.positions[t[1]], c = sphere.positions[t[2]];
      const Vec3 n = glm::cross(b - a, c - a);
      if (std::abs(glm::dot(p - a, n)) > 1e-12 * glm::length(n)) continue;
      const double wa = glm::dot(glm::cross(b - p, c - p), n) / glm::dot(n, n);
      const double wb = glm::dot(glm::cross(c - p, a - p), n) / glm::dot(n, n);
      const double wc = 1.0 - wa - wb;
      if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
      normal = glm::normalize(wa * base.vertex_normals[t[0]] + wb * base.vertex_normals[t[1]] +
                              wc * base.vertex_normals[t[2]]);
    }
    ASSERT_NE(normal, Vec3(0.0)) << "vertex " << v << " lies in no base face";
    const Vec3 moved = relief.mesh.positions[v] - p;
    EXPECT_NEAR(glm::length(moved - expected * normal), 0.0, 1e-9);
  }
  EXPECT_TRUE(inspect_surface(relief.mesh).closed_manifold());
  EXPECT_THROW(relief_surface(sphere, grey(0.6), {}, ReliefOptions{options.paint, -1.0}, *cpu()), InputError);
}

TEST(SurfaceRelief, AHollowTooTightIsClampedAndStaysClosedWithoutSelfIntersections) {
  // A torus with a hole of radius 0.1 and a relief of 0.5: raised in full, the inner side
  // passes through itself across the hole.
  const TriMesh ring = test::torus(0.4, 0.3, 32, 12);
  ReliefOptions options;
  options.paint.pixels_per_unit = 12.0;
  options.height = 0.5;
  const ReliefResult relief = relief_surface(ring, grey(1.0), {}, options, *cpu());
  EXPECT_GT(relief.clamped, 0);
  EXPECT_TRUE(inspect_surface(relief.mesh).closed_manifold());
  EXPECT_EQ(self_intersections(relief.mesh), 0u);
  // Where nothing is in the way (the outer side) the height is the whole of it.
  double highest = 0.0;
  for (double h : relief.heights) highest = std::max(highest, h);
  EXPECT_NEAR(highest, 0.5, 1e-9);
  // The same heights unclamped do pass through themselves.
  const TriMesh refined = split_faces(ring, relief.levels);
  const BaseSurface surface(refined);
  TriMesh unclamped = refined;
  for (size_t v = 0; v < refined.num_vertices(); ++v) unclamped.positions[v] += 0.5 * surface.vertex_normals[v];
  EXPECT_GT(self_intersections(unclamped), 0u);
}

TEST(SurfaceRelief, NoFaceTurnsOverAtSteepSteps) {
  // A checkerboard of black and white pixels raised high over a coarse icosahedron: the steps
  // are walls, and the smooth normals lean across them by up to half the base's dihedral angle.
  const TriMesh coarse = test::icosphere(0);
  ColourImage checker;
  checker.width = checker.height = 8;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) checker.rgb.emplace_back(glm::dvec3((x + y) % 2 ? 1.0 : 0.0));
  ReliefOptions options;
  options.paint.pixels_per_unit = 12.0;
  const double height = 0.8;
  options.height = height;
  const ReliefResult relief = relief_surface(coarse, checker, {}, options, *cpu());
  const TriMesh refined = split_faces(coarse, relief.levels);
  ASSERT_EQ(relief.mesh.triangles, refined.triangles);
  size_t turned = 0;
  for (const Tri& t : refined.triangles) {
    const auto normal = [&](const TriMesh& m) {
      return glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    };
    turned += glm::dot(normal(relief.mesh), normal(refined)) < 0.0;
  }

  // Heights are the signal (the output's grey) averaged half and half with the neighbours':
  // so wherever nothing was clamped or lowered, which is almost everywhere.
  const BaseSurface surface(refined);
  size_t averaged = 0, raw = 0;
  for (size_t v = 0; v < refined.num_vertices(); ++v) {
    const double s = relief.mesh.colors[v][0] / 255.0;
    double mean = 0.0;
    for (const auto& [u, length] : surface.edges[v]) mean += relief.mesh.colors[u][0] / 255.0;
    mean /= static_cast<double>(surface.edges[v].size());
    averaged += std::abs(relief.heights[v] - height * (0.5 * s + 0.5 * mean)) < 1e-9;
    raw += std::abs(relief.heights[v] - height * s) < 1e-9;
  }
  EXPECT_GT(averaged, 95 * refined.num_vertices() / 100);
  EXPECT_LT(raw, refined.num_vertices() / 2);
  EXPECT_EQ(turned, 0u);  // raised in full, 12 faces turn over
  // By lowering a few corners, not by flattening the relief.
  EXPECT_GT(relief.lowered_crossing, 0);
  EXPECT_LT(relief.lowered_crossing, static_cast<int>(refined.num_vertices()) / 50);
  EXPECT_TRUE(inspect_surface(relief.mesh).closed_manifold());
  EXPECT_EQ(self_intersections(relief.mesh), 0u);
}

TEST(SurfaceRelief, ABaseThatCrossesItselfIsReportedAndLeftAtItsOwnSurfaceThere) {
  // Two unit spheres 1.2 apart, one mesh: they cross on a circle whatever the heights.
  const TriMesh one = test::icosphere(2);
  TriMesh both = one;
  const int32_t offset = static_cast<int32_t>(one.num_vertices());
  for (const Vec3& p : one.positions) both.positions.push_back(p + Vec3(1.2, 0.0, 0.0));
  for (const Tri& t : one.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  ReliefOptions options;
  options.paint.pixels_per_unit = 6.0;
  options.height = 0.05;
  const ReliefResult relief = relief_surface(both, grey(1.0), {}, options, *cpu());
  EXPECT_GT(relief.crossing_left, 0u);
  EXPECT_EQ(relief.crossing_left, self_intersections(relief.mesh));
  // Away from the crossing circle (x = 0.6) every vertex keeps its whole height.
  const TriMesh refined = split_faces(both, relief.levels);
  for (size_t v = 0; v < refined.num_vertices(); ++v)
    if (std::abs(refined.positions[v].x - 0.6) > 0.3) {
      EXPECT_NEAR(relief.heights[v], 0.05, 1e-12) << v;
    }
  // A single sphere is left with nothing crossing.
  EXPECT_EQ(relief_surface(one, grey(1.0), {}, options, *cpu()).crossing_left, 0u);
}

}  // namespace
}  // namespace meshquilt
