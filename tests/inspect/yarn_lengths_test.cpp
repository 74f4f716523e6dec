// Yarn lengths in closed form: a capped cylinder and a bent tube (a torus section closed by flat
// caps) against their lengths and radii; translation does not change them; the weighted median
// against a hand count; the generator's weave yarns span their swatch.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/common.hpp>

#include "inspect/yarn_lengths.h"
#include "mesh/topology.h"
#include "swatch/weave.h"

namespace meshquilt {
namespace {

// A tube of radius r along a circular arc of radius R and angle `sweep` (R = 0: a straight tube
// of length `sweep` along x), n segments along, k around, closed by flat fan caps.
TriMesh tube(double r, double R, double sweep, int n, int k, const Vec3& shift = Vec3(0.0)) {
  TriMesh m;
  const auto centre = [&](double s) {
    return R > 0.0 ? Vec3(R * std::cos(s * sweep), R * std::sin(s * sweep), 0.0) : Vec3(s * sweep, 0.0, 0.0);
  };
  const auto out = [&](double s) { return R > 0.0 ? Vec3(std::cos(s * sweep), std::sin(s * sweep), 0.0) : Vec3(0, 1, 0); };
  // The cross-section's second axis, so that (out, up) turns about the tube's direction and the
  // faces face outward either way.
  const Vec3 up = R > 0.0 ? Vec3(0, 0, -1) : Vec3(0, 0, 1);
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    for (int j = 0; j < k; ++j) {
      const double t = 2.0 * std::numbers::pi * j / k;
      m.positions.push_back(shift + centre(s) + r * (std::cos(t) * out(s) + std::sin(t) * up));
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      const int a = i * k + j, b = i * k + (j + 1) % k, c = a + k, d = b + k;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  const int first = static_cast<int>(m.positions.size());
  m.positions.push_back(shift + centre(0.0));
  m.positions.push_back(shift + centre(1.0));
  for (int j = 0; j < k; ++j) {
    m.triangles.push_back({first, (j + 1) % k, j});
    m.triangles.push_back({first + 1, n * k + j, n * k + (j + 1) % k});
  }
  return m;
}

TubeMeasures measure(const TriMesh& m) {
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(m, &elements);
  EXPECT_EQ(elements, 1);
  return tube_measures(m, face_element, elements);
}

TEST(YarnLengths, CylindersAndBentTubesInClosedForm) {
  // A fine straight tube: L' = (L + r)^2 / L with the caps, r' = r L / (L + r) (A = 2 pi r (L + r),
  // V = pi r^2 L), up to the polygon's shortfall from a circle.
  const double r = 0.1, L = 5.0;
  const TubeMeasures straight = measure(tube(r, 0.0, L, 50, 256));
  EXPECT_NEAR(straight.length[0], (L + r) * (L + r) / L, 1e-3 * L);
  EXPECT_NEAR(straight.radius[0], r * L / (L + r), 1e-3 * r);
  // Bent along a quarter circle of radius 3: the centre line's length, as for a straight tube
  // (Pappus: area and volume both follow the centre line).
  const double R = 3.0, sweep = 0.5 * std::numbers::pi;
  const TubeMeasures bent = measure(tube(r, R, sweep, 400, 256));
  EXPECT_NEAR(bent.length[0], (R * sweep + r) * (R * sweep + r) / (R * sweep), 1e-3 * R * sweep);
  // Far from the origin nothing changes.
  const TubeMeasures moved = measure(tube(r, R, sweep, 400, 256, Vec3(1e6, -2e6, 3e5)));
  EXPECT_NEAR(moved.length[0], bent.length[0], 1e-6 * bent.length[0]);
}

TEST(YarnLengths, LengthWeightedMedian) {
  // Total 10: lengths up to 3 make 1 + 1 + 3 = 5, half of it.
  EXPECT_DOUBLE_EQ(length_weighted_median({3.0, 1.0, 5.0, 1.0, 0.0}), 3.0);
  EXPECT_DOUBLE_EQ(length_weighted_median({1.0, 1.0, 1.0, 10.0}), 10.0);
  EXPECT_DOUBLE_EQ(length_weighted_median({}), 0.0);
}

TEST(YarnLengths, TheGeneratorsYarnsSpanTheirSwatch) {
  const TriMesh weave = make_weave(WeaveOptions::small());
  int32_t elements = 0;
  const std::vector<int32_t> face_element = face_components(weave, &elements);
  const TubeMeasures tubes = tube_measures(weave, face_element, elements);
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : weave.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // Crimped yarns with their ends are a little longer than the swatch, never shorter.
  const double median = length_weighted_median(tubes.length);
  EXPECT_GT(median, 0.95 * std::min(hi.x - lo.x, hi.y - lo.y));
  EXPECT_LT(median, 1.5 * std::max(hi.x - lo.x, hi.y - lo.y));
}

}  // namespace
}  // namespace meshquilt
