// The shared layout of a base: the smoothest n-direction field in closed-form cases and against
// Poincare-Hopf, the layout's seams, and windows of it, which must differ from each other by a
// rotation through a multiple of 2 pi / n plus a translation, to rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "surface/conformal_patch.h"
#include "surface/direction_field.h"
#include "surface/base_layout.h"
#include "surface/seamless_layout.h"
#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

DirectionField smoothest(const BaseSurface& base, int n, const Vec3& along = Vec3(1.0, 0.0, 0.0)) {
  std::vector<Vec3> target(base.mesh.num_faces(), along);
  return smoothest_direction_field(base, n, target, std::vector<double>(target.size(), default_field_weight(base)));
}

int index_sum(const std::vector<int>& index) {
  int sum = 0;
  for (int i : index) sum += i;
  return sum;
}

TEST(DirectionField, IndicesOfASphereSumToNTimesTwo) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  for (int n : {1, 2, 4}) {
    const std::vector<int> index = field_indices(base, smoothest(base, n));
    int cones = 0;
    for (int i : index) cones += i != 0;
    EXPECT_EQ(index_sum(index), 2 * n) << "n = " << n;
    // The smoothest vector and line fields spread their singularities into 2n cones of index 1 / n.
    if (n <= 2) {
      EXPECT_EQ(cones, 2 * n) << "n = " << n;
    }
  }
}

TEST(DirectionField, AConstantTargetOnAPlaneIsKeptExactly) {
  const TriMesh sheet = test::flat_grid(12, 9, 0.1, 0.25);
  const BaseSurface base(sheet);
  const Vec3 along = glm::normalize(Vec3(1.0, 0.4, 0.0));
  for (int n : {1, 2, 4}) {
    const DirectionField field = smoothest(base, n, along);
    for (const Vec3& d : field.directions) {
      // One of the n directions is `along`: n times the angle between them is a whole turn.
      const double angle = std::atan2(glm::cross(along, d).z, glm::dot(along, d));
      EXPECT_NEAR(std::remainder(n * angle, 2.0 * std::numbers::pi), 0.0, 1e-9) << "n = " << n;
    }
  }
}

// Per face: the 2 x 2 map from the face's tangent plane to the layout, as singular values.
std::pair<double, double> stretch(const BaseSurface& base, const SeamlessLayout& layout, size_t f) {
  const Tri& t = base.mesh.triangles[f];
  const Vec3 p0 = base.mesh.positions[t[0]], p1 = base.mesh.positions[t[1]], p2 = base.mesh.positions[t[2]];
  const Vec3 e1 = glm::normalize(p1 - p0), e2 = glm::cross(base.face_normals[f], e1);
  const glm::dvec2 q1(glm::dot(p1 - p0, e1), 0.0), q2(glm::dot(p2 - p0, e1), glm::dot(p2 - p0, e2));
  const glm::dvec2 a = layout.uv[layout.corner_wedge[3 * f]], b = layout.uv[layout.corner_wedge[3 * f + 1]] - a,
                   c = layout.uv[layout.corner_wedge[3 * f + 2]] - a;
  const double det = q1.x * q2.y;
  const double j00 = (b.x * q2.y) / det, j01 = (c.x * q1.x - b.x * q2.x) / det;
  const double j10 = (b.y * q2.y) / det, j11 = (c.y * q1.x - b.y * q2.x) / det;
  const double e = 0.5 * (j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11), d = j00 * j11 - j01 * j10;
  const double s1 = std::sqrt(e + std::sqrt(std::max(0.0, e * e - d * d)));
  return {s1, d / s1};
}

TEST(SeamlessLayout, AConstantFieldOnAPlaneLaysItOutIsometrically) {
  const TriMesh sheet = test::flat_grid(10, 10, 0.1, 0.2);
  const BaseSurface base(sheet);
  const SeamlessLayout layout = seamless_layout(base, smoothest(base, 2, Vec3(0.6, 0.8, 0.0)));
  EXPECT_TRUE(layout.cones.empty());
  EXPECT_EQ(layout.flipped_faces, 0);
  for (size_t f = 0; f < sheet.num_faces(); ++f) {
    const auto [largest, smallest] = stretch(base, layout, f);
    EXPECT_NEAR(largest, 1.0, 1e-6);
    EXPECT_NEAR(smallest, 1.0, 1e-6);
  }
}

TEST(SeamlessLayout, SeamsAreRotationsByTheSymmetryPlusTranslations) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  const SeamlessLayout layout = seamless_layout(base, smoothest(base, 2));
  EXPECT_EQ(layout.cones.size(), 4u);
  EXPECT_EQ(layout.flipped_faces, 0);
  int seams = 0;
  for (size_t f = 0; f < sphere.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t g = base.face_across[f][k];
      if (!layout.cut[f][k]) continue;
      ++seams;
      const Tri& t = sphere.triangles[f];
      const Tri& tg = sphere.triangles[g];
      const auto corner = [](const Tri& tri, int32_t v) { return tri[0] == v ? 0 : tri[1] == v ? 1 : 2; };
      const int32_t a = t[k], b = t[(k + 1) % 3];
      const glm::dvec2 in_f = layout.uv[layout.corner_wedge[3 * f + corner(t, b)]] - layout.uv[layout.corner_wedge[3 * f + corner(t, a)]];
      const glm::dvec2 in_g = layout.uv[layout.corner_wedge[3 * g + corner(tg, b)]] - layout.uv[layout.corner_wedge[3 * g + corner(tg, a)]];
      // The edge seen from g is the edge seen from f turned back by the seam's turn.
      const glm::dvec2 expected = quarter_turned(in_f, -2 * layout.turn[f][k]);
      EXPECT_NEAR(glm::length(in_g - expected), 0.0, 1e-6 * glm::length(in_f));
    }
  EXPECT_GT(seams, 0);
}

// The largest distance of a seam's translation (U_g(x) - R U_f(x) at both ends of every cut
// edge) from a period of the lattice a, b, in periods.
double worst_seam_off_lattice(const BaseSurface& base, const SeamlessLayout& layout, const glm::dvec2& a,
                              const glm::dvec2& b) {
  const auto corner = [](const Tri& tri, int32_t v) { return tri[0] == v ? 0 : tri[1] == v ? 1 : 2; };
  const double det = a.x * b.y - a.y * b.x;
  double worst = 0.0;
  for (size_t f = 0; f < base.mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      if (!layout.cut[f][k]) continue;
      const int32_t g = base.face_across[f][k];
      const Tri& t = base.mesh.triangles[f];
      for (int32_t v : {t[k], t[(k + 1) % 3]}) {
        const glm::dvec2 in_f = layout.uv[layout.corner_wedge[3 * f + corner(t, v)]];
        const glm::dvec2 in_g = layout.uv[layout.corner_wedge[3 * g + corner(base.mesh.triangles[g], v)]];
        const glm::dvec2 d = in_g - quarter_turned(in_f, 2 * layout.turn[f][k]);
        const double k0 = (d.x * b.y - d.y * b.x) / det, k1 = (a.x * d.y - a.y * d.x) / det;
        worst = std::max({worst, std::abs(k0 - std::round(k0)), std::abs(k1 - std::round(k1))});
      }
    }
  return worst;
}

TEST(SeamlessLayout, OnALatticeEverySeamContinuesByAPeriod) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  const DirectionField field = smoothest(base, 2);
  const glm::dvec2 a(0.13, 0.0), b(0.05, 0.21);
  const SeamlessLayout free = seamless_layout(base, field);
  const SeamlessLayout rounded = seamless_layout(base, field, std::array<glm::dvec2, 2>{a, b});
  EXPECT_FALSE(free.on_lattice);
  EXPECT_TRUE(rounded.on_lattice);
  // Left free, the seams' translations are whatever the solve gives; rounded, each is a period
  // (a half turn's too: the layout's origin is a point the texture turns about).
  EXPECT_GT(worst_seam_off_lattice(base, free, a, b), 0.05);
  EXPECT_LT(worst_seam_off_lattice(base, rounded, a, b), 1e-6);
  EXPECT_EQ(rounded.flipped_faces, 0);
}

double layout_area(const BaseSurface& base, const SeamlessLayout& layout) {
  double area = 0.0;
  for (size_t f = 0; f < base.mesh.num_faces(); ++f) {
    const glm::dvec2 a = layout.uv[layout.corner_wedge[3 * f]], b = layout.uv[layout.corner_wedge[3 * f + 1]],
                     c = layout.uv[layout.corner_wedge[3 * f + 2]];
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

// Elements k times the size: the free layout is the same one shrunk by k; on a lattice its seams
// still continue by periods, with about 1 / k^2 the area.
TEST(SeamlessLayout, ElementScaleShrinksTheLayoutAndKeepsItsSeamsOnTheLattice) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  const DirectionField field = smoothest(base, 2);
  const double k = 1.25;
  const SeamlessLayout free = seamless_layout(base, field);
  const SeamlessLayout free_scaled = seamless_layout(base, field, std::nullopt, kDefaultSizeHold, k);
  ASSERT_EQ(free.uv.size(), free_scaled.uv.size());
  for (size_t w = 0; w < free.uv.size(); ++w) EXPECT_NEAR(glm::length(free_scaled.uv[w] * k - free.uv[w]), 0.0, 1e-9);

  const std::array<glm::dvec2, 2> lattice{glm::dvec2(0.13, 0.0), glm::dvec2(0.05, 0.21)};
  const SeamlessLayout rounded = seamless_layout(base, field, lattice);
  const SeamlessLayout scaled = seamless_layout(base, field, lattice, kDefaultSizeHold, k);
  EXPECT_TRUE(scaled.on_lattice);
  EXPECT_LT(worst_seam_off_lattice(base, scaled, lattice[0], lattice[1]), 1e-6);
  EXPECT_EQ(scaled.flipped_faces, 0);
  EXPECT_NEAR(layout_area(base, scaled) * k * k / layout_area(base, rounded), 1.0, 0.1);
}

// Plane position of every base vertex of a patch (the first copy where it is slit).
std::map<int32_t, glm::dvec2> plane_of(const SurfacePatch& patch) {
  std::map<int32_t, glm::dvec2> result;
  for (size_t k = 0; k < patch.vertices.size(); ++k) result.emplace(patch.vertices[k], patch.uv[k]);
  return result;
}

TEST(SeamlessLayout, OverlappingWindowsDifferByASymmetryTurnAndATranslation) {
  // The default job's base; split once by the layout (320 faces hold no four half cones).
  const TriMesh sphere = test::icosphere(2);
  const BaseSurface base(sphere);
  std::vector<Vec3> target(sphere.num_faces(), Vec3(1.0, 0.0, 0.0));
  const BaseLayout layout(base, 2, target, std::vector<double>(target.size(), default_field_weight(base)));
  EXPECT_EQ(layout.levels(), 1);
  EXPECT_EQ(layout.cones(), 4);
  int compared = 0;
  for (int32_t first = 0; first < 320; first += 23) {
    const SurfacePatch a = grow_conformal_patch(base, {first, glm::dvec2(0.3)}, 0.5, nullptr, &layout);
    const int32_t second = base.face_across[base.face_across[first][0]][1];
    const SurfacePatch b = grow_conformal_patch(base, {second, glm::dvec2(0.2)}, 0.5, nullptr, &layout);
    if (a.chart != PatchChart::layout_window || b.chart != PatchChart::layout_window) continue;
    // Shared vertices that neither patch slit: b's plane = R a's plane + t, R a half turn or none.
    std::vector<std::pair<glm::dvec2, glm::dvec2>> pairs;
    const auto in_a = plane_of(a), in_b = plane_of(b);
    const auto copies = [](const SurfacePatch& p, int32_t v) { return std::count(p.vertices.begin(), p.vertices.end(), v); };
    for (const auto& [v, p] : in_a)
      if (const auto it = in_b.find(v); it != in_b.end() && copies(a, v) == 1 && copies(b, v) == 1) pairs.emplace_back(p, it->second);
    if (pairs.size() < 3) continue;
    double best = std::numeric_limits<double>::max();
    for (int quarter : {0, 2}) {
      const glm::dvec2 t = pairs[0].second - quarter_turned(pairs[0].first, quarter);
      double worst = 0.0;
      for (const auto& [pa, pb] : pairs) worst = std::max(worst, glm::length(pb - quarter_turned(pa, quarter) - t));
      best = std::min(best, worst);
    }
    EXPECT_LT(best, 1e-6) << "patches at faces " << first << " and " << second;
    ++compared;
  }
  EXPECT_GE(compared, 5);
}

// The layout window alone (what the fill asks for) is the patch grow_conformal_patch makes where
// that patch is a layout window, and nothing where it falls back to another chart: balls that
// cover the sphere's four cones fold.
TEST(BaseLayout, AGrownLayoutWindowIsThePatchsWindowOrNone) {
  const TriMesh sphere = test::icosphere(2);
  const BaseSurface base(sphere);
  std::vector<Vec3> target(sphere.num_faces(), Vec3(1.0, 0.0, 0.0));
  const BaseLayout layout(base, 2, target, std::vector<double>(target.size(), default_field_weight(base)));
  int windows = 0, none = 0;
  for (const double radius : {0.6, 3.0})
    for (int32_t face = 0; face < 320; face += 3) {
      const SurfacePoint seed{face, glm::dvec2(0.3, 0.25)};
      const SurfacePatch patch = grow_conformal_patch(base, seed, radius, nullptr, &layout);
      const std::optional<SurfacePatch> window = grow_layout_window(base, seed, radius, layout);
      ASSERT_EQ(window.has_value(), patch.chart == PatchChart::layout_window) << "seed face " << face;
      if (!window) {
        ++none;
        continue;
      }
      ++windows;
      EXPECT_EQ(window->faces, patch.faces);
      EXPECT_EQ(window->vertices, patch.vertices);
      ASSERT_EQ(window->uv.size(), patch.uv.size());
      for (size_t k = 0; k < patch.uv.size(); ++k) EXPECT_EQ(window->uv[k], patch.uv[k]);
      EXPECT_EQ(window->flipped_faces, 0);
    }
  std::printf("%d layout windows, %d folded\n", windows, none);
  EXPECT_GT(windows, 100);
  EXPECT_GT(none, 10);
}

// Whether a point lies inside a plane triangle by more than `margin` of its barycentrics.
bool strictly_inside(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double margin) {
  const double area = test::signed_area2(a, b, c);
  if (area == 0.0) return false;
  const double u = test::signed_area2(p, b, c) / area, v = test::signed_area2(a, p, c) / area;
  return u > margin && v > margin && 1.0 - u - v > margin;
}

TEST(SeamlessLayout, AWindowRoundANegativeConeDoesNotWrapOverItself) {
  // A drawn field turning once backwards round the middle of a flat square: a cone of index -1,
  // round which the layout spans 4 pi. The grid is jittered so the two sheets' faces do not
  // line up.
  TriMesh grid = test::flat_grid(40, 40, 0.05);
  {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.015, 0.015);
    for (Vec3& p : grid.positions)
      if (p.x > 0.0 && p.y > 0.0 && p.x < 2.0 && p.y < 2.0) p += Vec3(jitter(rng), jitter(rng), 0.0);
  }
  const BaseSurface base(grid);
  const glm::dvec2 middle(1.0, 1.0);
  std::vector<Vec3> target(grid.num_faces());
  for (size_t f = 0; f < grid.num_faces(); ++f) {
    const Vec3 c = base.position({static_cast<int32_t>(f), glm::dvec2(1.0 / 3.0)});
    const double angle = -std::atan2(c.y - middle.y, c.x - middle.x);
    target[f] = Vec3(std::cos(angle), std::sin(angle), 0.0);
  }
  const BaseLayout layout(base, 1, target, std::vector<double>(target.size(), guided_field_weight(base)), true);
  ASSERT_GE(layout.cones(), 1);
  int windows = 0;
  for (const glm::dvec2 seed : {glm::dvec2(0.913, 0.962), glm::dvec2(1.118, 1.031), glm::dvec2(1.012, 0.874)}) {
    // The grid's face holding the seed: cell (i, j), either half.
    int32_t face = -1;
    glm::dvec2 bary(0.0);
    for (size_t f = 0; f < grid.num_faces() && face < 0; ++f) {
      const Tri& t = grid.triangles[f];
      const glm::dvec2 a(grid.positions[t[0]]), b(grid.positions[t[1]]), c(grid.positions[t[2]]);
      if (!strictly_inside(seed, a, b, c, 0.0)) continue;
      const double area = test::signed_area2(a, b, c);
      face = static_cast<int32_t>(f);
      bary = glm::dvec2(test::signed_area2(a, seed, c) / area, test::signed_area2(a, b, seed) / area);
    }
    ASSERT_GE(face, 0);
    const SurfacePatch patch = grow_conformal_patch(base, {face, bary}, 0.4, nullptr, &layout);
    if (patch.chart != PatchChart::layout_window) continue;
    ++windows;
    // No face's centre lies inside another face that shares no vertex with it.
    int overlaps = 0;
    for (size_t f = 0; f < patch.faces.size(); ++f) {
      const int32_t* vf = &patch.local_vertex_of_face_[3 * f];
      const glm::dvec2 centre = (patch.uv[vf[0]] + patch.uv[vf[1]] + patch.uv[vf[2]]) / 3.0;
      const Tri& tf = grid.triangles[patch.faces[f]];
      for (size_t g = 0; g < patch.faces.size(); ++g) {
        const Tri& tg = grid.triangles[patch.faces[g]];
        if (std::find_first_of(tf.begin(), tf.end(), tg.begin(), tg.end()) != tf.end()) continue;
        const int32_t* vg = &patch.local_vertex_of_face_[3 * g];
        overlaps += strictly_inside(centre, patch.uv[vg[0]], patch.uv[vg[1]], patch.uv[vg[2]], 1e-6);
      }
    }
    EXPECT_EQ(overlaps, 0) << "window at " << seed.x << ", " << seed.y << " of " << patch.faces.size() << " faces";
    // Nearest first, the window keeps a whole disk slit where its two sheets meet: the plane
    // round the seed is covered but for the slit (dropping the farther face of each overlapping
    // pair left 7-10% of it bare, in both sheets).
    SurfacePatch indexed = patch;
    indexed.index();
    int inside = 0, covered = 0;
    for (double x = -0.1; x <= 0.1; x += 0.005)
      for (double y = -0.1; y <= 0.1; y += 0.005) {
        if (x * x + y * y > 0.01) continue;
        ++inside;
        covered += indexed.locate(glm::dvec2(x, y)).has_value();
      }
    EXPECT_GE(covered, 0.95 * inside) << "window at " << seed.x << ", " << seed.y;
  }
  EXPECT_GE(windows, 2);
}

TEST(BaseLayout, SplitFacesKeepTheSurfaceAndNumberThePartsOfEachFace) {
  const TriMesh sphere = test::icosphere(1);
  const TriMesh split = split_faces(sphere, 2);
  ASSERT_EQ(split.num_faces(), 16 * sphere.num_faces());
  for (size_t v = 0; v < sphere.num_vertices(); ++v) EXPECT_EQ(split.positions[v], sphere.positions[v]);
  for (size_t f = 0; f < sphere.num_faces(); ++f) {
    const Tri& t = sphere.triangles[f];
    const Vec3 normal = glm::cross(sphere.positions[t[1]] - sphere.positions[t[0]], sphere.positions[t[2]] - sphere.positions[t[0]]);
    double area = 0.0;
    for (size_t p = 16 * f; p < 16 * f + 16; ++p) {
      const Tri& s = split.triangles[p];
      const Vec3 n = glm::cross(split.positions[s[1]] - split.positions[s[0]], split.positions[s[2]] - split.positions[s[0]]);
      EXPECT_GT(glm::dot(n, normal), 0.0);  // same orientation, in the parent's plane
      area += glm::length(n);
    }
    EXPECT_NEAR(area, glm::length(normal), 1e-12);
    // Corner c of the face is corner c of part c x 5 (the layout's windows rely on it).
    for (int c = 0; c < 3; ++c) EXPECT_EQ(split.triangles[16 * f + 5 * c][c], t[c]);
  }
}

}  // namespace
}  // namespace meshquilt
