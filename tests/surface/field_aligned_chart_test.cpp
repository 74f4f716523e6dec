// Field-aligned charts in closed form: on a flat sheet with a constant field the chart is the
// sheet itself turned so the field runs along +x; on a cylinder with the field along its axis
// (developable: an isometry exists) the chart is axial length by arc length, and two
// overlapping patches' charts then differ by a translation alone.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include <glm/geometric.hpp>

#include "surface/base_layout.h"
#include "surface/conformal_patch.h"
#include "surface/field_aligned_chart.h"

namespace meshquilt {
namespace {

// An n x n grid of unit squares in the x-y plane, slightly sheared so no edge is axis aligned.
TriMesh sheet(int n) {
  TriMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back(Vec3(i + 0.3 * j, j, 0.0));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      m.triangles.push_back({v, v + 1, v + n + 2});
      m.triangles.push_back({v, v + n + 2, v + n + 1});
    }
  return m;
}

// A cylinder of radius r about the z axis: `around` segments, `rows` rows of height h.
TriMesh cylinder(double r, int around, int rows, double h) {
  TriMesh m;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < around; ++i) {
      const double t = 2.0 * std::numbers::pi * i / around;
      m.positions.push_back(Vec3(r * std::cos(t), r * std::sin(t), j * h));
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < around; ++i) {
      const int a = j * around + i, b = j * around + (i + 1) % around;
      m.triangles.push_back({a, b, b + around});
      m.triangles.push_back({a, b + around, a + around});
    }
  return m;
}

// The shared layout of a field along d everywhere (a vector field: no cones on these bases).
std::unique_ptr<BaseLayout> constant_layout(const BaseSurface& base, const Vec3& d) {
  const std::vector<Vec3> target(base.mesh.num_faces(), d);
  return std::make_unique<BaseLayout>(base, 1, target, std::vector<double>(target.size(), default_field_weight(base)));
}

TEST(FieldAlignedChart, AFlatSheetTurnsItsFieldOntoX) {
  const TriMesh m = sheet(6);
  const BaseSurface base(m);
  const Vec3 d = glm::normalize(Vec3(1.0, 2.0, 0.0));
  const auto layout = constant_layout(base, d);
  const SurfacePatch patch = grow_conformal_patch(base, {20, glm::dvec2(0.3, 0.3)}, 3.0, nullptr, layout.get());
  ASSERT_EQ(patch.chart, PatchChart::layout_window);
  EXPECT_EQ(patch.flipped_faces, 0);
  EXPECT_NEAR(patch.area_distortion, 1.0, 1e-6);
  // u = <p - seed, d>, v = <p - seed, z x d>.
  const Vec3 seed = base.position({20, glm::dvec2(0.3, 0.3)});
  const Vec3 e = glm::cross(Vec3(0, 0, 1), d);
  for (size_t k = 0; k < patch.vertices.size(); ++k) {
    const Vec3 p = m.positions[patch.vertices[k]] - seed;
    EXPECT_NEAR(patch.uv[k].x, glm::dot(p, d), 1e-6);
    EXPECT_NEAR(patch.uv[k].y, glm::dot(p, e), 1e-6);
  }
}

TEST(FieldAlignedChart, ACylinderUnrollsAndOverlappingChartsDifferByATranslation) {
  const double r = 2.0;
  const TriMesh m = cylinder(r, 48, 20, 0.25);
  const BaseSurface base(m);
  const auto along_axis = constant_layout(base, Vec3(0, 0, 1));
  const SurfacePoint a{48 * 2 * 8 + 10, glm::dvec2(0.2, 0.3)}, b{48 * 2 * 10 + 14, glm::dvec2(0.4, 0.1)};
  const SurfacePatch pa = grow_conformal_patch(base, a, 2.0, nullptr, along_axis.get());
  const SurfacePatch pb = grow_conformal_patch(base, b, 2.0, nullptr, along_axis.get());
  ASSERT_EQ(pa.chart, PatchChart::layout_window);
  ASSERT_EQ(pb.chart, PatchChart::layout_window);
  // Unrolled: u is height, |v| grows with arc length. The layout keeps one even scale, so height
  // gives up the chord-to-arc ratio of one segment (1 - 3e-6 here) to the way round.
  for (size_t k = 0; k < pa.vertices.size(); ++k)
    EXPECT_NEAR(pa.uv[k].x, m.positions[pa.vertices[k]].z - base.position(a).z, 2e-5);
  // Every vertex both patches hold sits at the same place up to one translation.
  glm::dvec2 shift(0.0);
  bool first = true;
  int shared = 0;
  for (size_t k = 0; k < pa.vertices.size(); ++k)
    for (size_t l = 0; l < pb.vertices.size(); ++l) {
      if (pa.vertices[k] != pb.vertices[l]) continue;
      const glm::dvec2 s = pb.uv[l] - pa.uv[k];
      if (first) shift = s, first = false;
      EXPECT_NEAR(s.x, shift.x, 1e-6);
      EXPECT_NEAR(s.y, shift.y, 1e-6);
      ++shared;
    }
  EXPECT_GT(shared, 20);
}

TEST(FieldAlignedChart, WithoutAFieldThePatchIsConformal) {
  const TriMesh m = sheet(4);
  const BaseSurface base(m);
  const SurfacePatch patch = grow_conformal_patch(base, {10, glm::dvec2(0.3, 0.3)}, 2.0);
  EXPECT_EQ(patch.chart, PatchChart::conformal);
}

}  // namespace
}  // namespace meshquilt
