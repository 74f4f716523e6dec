// The cone metric and its field: closed-form cases (a metric that asks for the surface's own
// curvature changes nothing), the field's singularities against its cones, and bases it refuses.
#include "surface/cone_metric_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "support/surface_fixtures.h"

namespace meshquilt {
namespace {

// A torus of `around` x `tube` quads, each split in two.
TriMesh torus(int around, int tube, double major = 1.0, double minor = 0.4) {
  TriMesh m;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2.0 * std::numbers::pi * i / around, v = 2.0 * std::numbers::pi * j / tube;
      m.positions.emplace_back((major + minor * std::cos(v)) * std::cos(u), (major + minor * std::cos(v)) * std::sin(u),
                               minor * std::sin(v));
    }
  const auto at = [&](int i, int j) { return static_cast<int32_t>(((i + around) % around) * tube + (j + tube) % tube); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// 2 pi less the angles round each vertex, summed corner by corner.
std::vector<double> defects(const TriMesh& m) {
  std::vector<double> k(m.num_vertices(), 2.0 * std::numbers::pi);
  for (const Tri& t : m.triangles)
    for (int c = 0; c < 3; ++c) {
      const Vec3 a = glm::normalize(m.positions[t[(c + 1) % 3]] - m.positions[t[c]]);
      const Vec3 b = glm::normalize(m.positions[t[(c + 2) % 3]] - m.positions[t[c]]);
      k[t[c]] -= std::acos(glm::dot(a, b));
    }
  return k;
}

TEST(ConeMetric, AskingForTheSurfacesOwnCurvatureScalesNothing) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  for (double phi : cone_metric_scale(base, defects(sphere))) EXPECT_NEAR(phi, 0.0, 1e-6);
}

TEST(ConeMetric, ACurvatureMovedToOneVertexGrowsLengthsThere) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  std::vector<double> k = defects(sphere);
  // Half of vertex 1's curvature moved onto vertex 0: lengths round 0 grow, round 1 shrink.
  k[0] += 0.5 * k[1];
  k[1] *= 0.5;
  const std::vector<double> phi = cone_metric_scale(base, k);
  for (size_t v = 2; v < phi.size(); ++v) {
    EXPECT_GT(phi[0], phi[v]);
    EXPECT_LT(phi[1], phi[v]);
  }
}

TEST(ConeMetricField, ItsSingularitiesAreItsConesOnASphere) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  for (int n : {1, 2, 4}) {
    const auto field = cone_metric_field(base, n, Vec3(1.0, 0.0, 0.0));
    ASSERT_TRUE(field) << "n = " << n;
    int cones = 0;
    for (int index : field_indices(base, *field)) {
      EXPECT_TRUE(index == 0 || index == 1) << "n = " << n << ": index " << index;
      cones += index;
    }
    EXPECT_EQ(cones, 2 * n) << "n = " << n;
  }
}

TEST(ConeMetricField, FourHalfTurnConesSitNearATetrahedronsCornersOnASphere) {
  // Four cones of a half turn scale a round sphere most evenly at a regular tetrahedron's
  // corners, 109.5 degrees apart; greedy placement alone puts them on a great circle, 90 and 180.
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  const auto field = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0));
  ASSERT_TRUE(field);
  std::vector<Vec3> cones;
  const std::vector<int> index = field_indices(base, *field);
  for (size_t v = 0; v < index.size(); ++v)
    if (index[v] != 0) cones.push_back(glm::normalize(sphere.positions[v]));
  ASSERT_EQ(cones.size(), 4u);
  for (size_t i = 0; i < cones.size(); ++i)
    for (size_t j = i + 1; j < cones.size(); ++j) {
      const double degrees = std::acos(glm::dot(cones[i], cones[j])) * 180.0 / std::numbers::pi;
      EXPECT_GT(degrees, 95.0) << i << ", " << j;
      EXPECT_LT(degrees, 125.0) << i << ", " << j;
    }
}

TEST(ConeMetricField, SpreadsScaleLessThanTheSmoothestFieldPulledToAnAxis) {
  const TriMesh sphere = test::icosphere(3);
  const BaseSurface base(sphere);
  // The axis projection's poles pair the smoothest line field's four cones there.
  std::vector<Vec3> target(sphere.num_faces());
  for (size_t f = 0; f < target.size(); ++f) {
    const Tri& t = sphere.triangles[f];
    const Vec3 c = (sphere.positions[t[0]] + sphere.positions[t[1]] + sphere.positions[t[2]]) / 3.0;
    target[f] = glm::cross(Vec3(0.0, 0.0, 1.0), c);
  }
  const DirectionField paired =
      smoothest_direction_field(base, 2, target, std::vector<double>(target.size(), default_field_weight(base)));
  const auto placed = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0));
  ASSERT_TRUE(placed);
  const double paired_spread = *field_scale_spread(base, paired), placed_spread = *field_scale_spread(base, *placed);
  std::printf("scale spread p90 / p10: smoothest %.3f, cones placed %.3f\n", paired_spread, placed_spread);
  EXPECT_LT(placed_spread, 0.85 * paired_spread);
}

// An icosphere with eight Gaussian bumps, as limbs or ears: four cones leave the tips of the
// others scaled far from the rest.
TriMesh bumpy_sphere() {
  TriMesh m = test::icosphere(4);
  // Eight bumps, near a cube's corners, more than four cones can round off.
  std::vector<Vec3> bumps;
  for (int i = 0; i < 8; ++i)
    bumps.push_back(glm::normalize(Vec3(i & 1 ? 1.0 : -1.0, i & 2 ? 1.1 : -0.9, i & 4 ? 1.2 : -0.8)));
  for (Vec3& p : m.positions) {
    double r = 1.0;
    for (const Vec3& d : bumps) {
      const double angle = std::acos(std::clamp(glm::dot(glm::normalize(p), d), -1.0, 1.0));
      r += 0.8 * std::exp(-(angle / 0.35) * (angle / 0.35));
    }
    p *= r;
  }
  return m;
}

struct ConeSet {
  std::vector<Vec3> positive, negative;
};

ConeSet cones_of(const TriMesh& m, const BaseSurface& base, const DirectionField& field) {
  ConeSet set;
  const std::vector<int> index = field_indices(base, field);
  for (size_t v = 0; v < index.size(); ++v) {
    EXPECT_TRUE(index[v] >= -1 && index[v] <= 1) << "vertex " << v << ": index " << index[v];
    if (index[v] > 0) set.positive.push_back(m.positions[v]);
    if (index[v] < 0) set.negative.push_back(m.positions[v]);
  }
  return set;
}

TEST(ConeMetricField, PairsOfConesNarrowTheScaleWhereFourLeaveItSpread) {
  const TriMesh m = bumpy_sphere();
  const BaseSurface base(m);
  const auto four = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0));
  ASSERT_TRUE(four);
  const ConeSet alone = cones_of(m, base, *four);
  EXPECT_EQ(alone.positive.size(), 4u);
  EXPECT_TRUE(alone.negative.empty());
  const double separation = 0.5;
  const auto paired = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0), ConeBound{1.0, separation, 16});
  ASSERT_TRUE(paired);
  const ConeSet with = cones_of(m, base, *paired);
  const double spread_alone = *field_scale_spread(base, *four), spread_with = *field_scale_spread(base, *paired);
  std::printf("bumpy sphere: 4 cones spread %.3f; %zu + %zu cones spread %.3f\n", spread_alone, with.positive.size(),
              with.negative.size(), spread_with);
  // Poincare-Hopf: every pair adds one cone of each sign.
  EXPECT_GT(with.negative.size(), 0u);
  EXPECT_EQ(with.positive.size(), 4u + with.negative.size());
  EXPECT_LT(spread_with, 0.8 * spread_alone);
  // Every cone keeps its distance from every other.
  std::vector<Vec3> all = with.positive;
  all.insert(all.end(), with.negative.begin(), with.negative.end());
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) EXPECT_GE(glm::length(all[i] - all[j]), separation * (1.0 - 1e-9));
  // A bound the four cones already meet adds none.
  const auto bounded = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0), ConeBound{spread_alone * 1.01, separation, 16});
  ASSERT_TRUE(bounded);
  EXPECT_TRUE(cones_of(m, base, *bounded).negative.empty());
  // A bound between stops at the first placement within it: no wider than asked, fewer cones.
  const double between = 0.5 * (spread_alone + spread_with);
  const auto fewer = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0), ConeBound{between, separation, 16});
  ASSERT_TRUE(fewer);
  EXPECT_LE(*field_scale_spread(base, *fewer), between);
  EXPECT_LE(cones_of(m, base, *fewer).negative.size(), with.negative.size());
}

// A disc keeps its border's lengths: a flat one needs no cone; the bumpy sphere cut open below
// gets cones inside it, of either sign, that narrow its scale.
TEST(ConeMetricField, ADiscsConesLieInsideItAndEvenItsScale) {
  const TriMesh grid = test::flat_grid(8, 8, 0.1);
  const BaseSurface flat(grid);
  const auto none = cone_metric_field(flat, 2, Vec3(1.0, 0.0, 0.0), ConeBound{1.0, 0.1, 8});
  ASSERT_TRUE(none);
  for (int index : field_indices(flat, *none)) EXPECT_EQ(index, 0);
  EXPECT_NEAR(*field_scale_spread(flat, *none), 1.0, 1e-6);

  const TriMesh closed = bumpy_sphere();
  TriMesh cap;
  cap.positions = closed.positions;
  for (const Tri& t : closed.triangles)
    if (closed.positions[t[0]].z + closed.positions[t[1]].z + closed.positions[t[2]].z > -1.5) cap.triangles.push_back(t);
  const BaseSurface base(cap);
  const auto bare = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0), ConeBound{1.0, 0.5, 0});
  const auto placed = cone_metric_field(base, 2, Vec3(1.0, 0.0, 0.0), ConeBound{1.0, 0.5, 16});
  ASSERT_TRUE(bare && placed);
  const ConeSet cones = cones_of(cap, base, *placed);
  const double bare_spread = *field_scale_spread(base, *bare), placed_spread = *field_scale_spread(base, *placed);
  std::printf("bumpy cap: no cones spread %.3f; %zu + %zu cones spread %.3f\n", bare_spread, cones.positive.size(),
              cones.negative.size(), placed_spread);
  for (int index : field_indices(base, *bare)) EXPECT_EQ(index, 0);
  EXPECT_GT(cones.positive.size(), 0u);
  EXPECT_LT(placed_spread, 0.8 * bare_spread);
  // field_indices reads no index at a border vertex; every cone placed is one of the field's.
  std::vector<Vec3> all = cones.positive;
  all.insert(all.end(), cones.negative.begin(), cones.negative.end());
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) EXPECT_GE(glm::length(all[i] - all[j]), 0.5 * (1.0 - 1e-9));
}

TEST(ConeMetricField, RefusesBasesThatAreNeitherOneSphereNorOneDisc) {
  const TriMesh ring = torus(24, 12);
  EXPECT_FALSE(cone_metric_field(BaseSurface(ring), 2, Vec3(1.0, 0.0, 0.0)));
  // An open tube: an annulus, two borders.
  TriMesh tube = ring;
  tube.triangles.resize(tube.triangles.size() - 2 * 12);
  EXPECT_FALSE(cone_metric_field(BaseSurface(tube), 2, Vec3(1.0, 0.0, 0.0)));
  TriMesh two = test::icosphere(1);
  const TriMesh other = test::icosphere(1, 0.5);
  const auto offset = static_cast<int32_t>(two.positions.size());
  for (const Vec3& p : other.positions) two.positions.push_back(p + Vec3(3.0, 0.0, 0.0));
  for (const Tri& t : other.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  EXPECT_FALSE(cone_metric_field(BaseSurface(two), 2, Vec3(1.0, 0.0, 0.0)));
}

}  // namespace
}  // namespace meshquilt
