// The convex x-y outline against brute force: a point is inside when it lies left of (or on)
// every edge, and grown by a margin when its distance to the hull is at most the margin.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "mesh/convex_outline.h"

namespace meshquilt {
namespace {

// Distance from p to the closed convex polygon (0 inside), by its edges, for counter-clockwise
// corners; written apart from ConvexOutline::contains, which tests edge lines only.
double distance_to_polygon(const std::vector<glm::dvec2>& c, const glm::dvec2& p) {
  bool inside = true;
  double best = INFINITY;
  for (size_t i = 0; i < c.size(); ++i) {
    const glm::dvec2 a = c[i], b = c[(i + 1) % c.size()];
    const glm::dvec2 e = b - a;
    inside = inside && (e.x * (p.y - a.y) - e.y * (p.x - a.x)) >= 0.0;
    const double s = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
    best = std::min(best, glm::length(p - (a + s * e)));
  }
  return inside ? 0.0 : best;
}

TEST(ConvexOutline, SquareWithInnerAndEdgePointsKeepsItsFourCorners) {
  std::vector<Vec3> points{{0, 0, 1}, {2, 0, -1}, {2, 2, 0}, {0, 2, 0}, {1, 1, 5}, {1, 0, 0}, {2, 1, 0}, {0, 0, 3}};
  const ConvexOutline outline(points);
  ASSERT_EQ(outline.corners().size(), 4u);
  const std::vector<glm::dvec2> expected{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_EQ(outline.corners(), expected);  // counter-clockwise from the lowest x, then y
  EXPECT_TRUE(outline.contains({1.0, 1.0}));
  EXPECT_TRUE(outline.contains({2.0, 1.0}));  // on an edge
  EXPECT_FALSE(outline.contains({2.1, 1.0}));
  EXPECT_TRUE(outline.contains({2.1, 1.0}, 0.1 + 1e-12));
  EXPECT_FALSE(outline.contains({-0.5, 1.0}, 0.4));
}

TEST(ConvexOutline, TurnedSquareLeavesItsBoundingBoxCornersOut) {
  // A square turned by 45 degrees: the corners of its bounding box lie outside, its centre in.
  std::vector<Vec3> points{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  const ConvexOutline outline(points);
  EXPECT_EQ(outline.corners().size(), 4u);
  EXPECT_TRUE(outline.contains({0.0, 0.0}));
  EXPECT_FALSE(outline.contains({0.9, 0.9}));
  // The bounding box's corner is sqrt(2)/2 from the hull's edge.
  EXPECT_FALSE(outline.contains({1.0, 1.0}, 0.70));
  EXPECT_TRUE(outline.contains({1.0, 1.0}, 0.71));
}

TEST(ConvexOutline, MatchesBruteForceOnRandomPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec3> points(3 + trial);
    for (Vec3& p : points) p = Vec3(u(rng), 0.5 * u(rng), 0.0);
    const ConvexOutline outline(points);
    const std::vector<glm::dvec2>& c = outline.corners();
    ASSERT_GE(c.size(), 3u);
    // Every input point lies inside; corners are input points.
    for (const Vec3& p : points) EXPECT_EQ(distance_to_polygon(c, glm::dvec2(p)), 0.0);
    for (const glm::dvec2& corner : c)
      EXPECT_TRUE(std::any_of(points.begin(), points.end(), [&](const Vec3& p) { return glm::dvec2(p) == corner; }));
    for (int k = 0; k < 40; ++k) {
      const glm::dvec2 q(1.5 * u(rng), 1.5 * u(rng));
      const double d = distance_to_polygon(c, q);
      EXPECT_EQ(outline.contains(q), d == 0.0) << trial;
      // Grown by a margin: the edge lines moved out hold at least the points within the margin
      // (and a little more at corners, never more than margin / sin(half the corner angle)).
      if (d <= 0.1) EXPECT_TRUE(outline.contains(q, 0.1));
      // Outside, the distance to the boundary is the distance to the polygon.
      if (d > 0.0) EXPECT_NEAR(outline.boundary_distance(q), d, 1e-12);
    }
  }
}

TEST(ConvexOutline, WidthIsTheNarrowestStripAnyWayTurned) {
  // A 6 x 0.4 bar turned by any angle is 0.4 wide, while its bounding box grows to about 4 x 4.
  for (double degrees : {0.0, 17.0, 45.0, 50.0, 90.0, 133.0}) {
    const double a = degrees * std::acos(-1.0) / 180.0;
    const glm::dvec2 along(std::cos(a), std::sin(a)), across(-std::sin(a), std::cos(a));
    std::vector<Vec3> points;
    for (double s : {-3.0, 3.0})
      for (double t : {-0.2, 0.2}) points.emplace_back(Vec3(s * along + t * across, 0.0));
    EXPECT_NEAR(ConvexOutline(points).width(), 0.4, 1e-12) << degrees;
  }
  // An equilateral triangle of side 2 is as wide as it is tall.
  const ConvexOutline triangle(std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0}});
  EXPECT_NEAR(triangle.width(), std::sqrt(3.0), 1e-12);
  EXPECT_EQ(ConvexOutline(std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}}).width(), 0.0);
}

TEST(ConvexOutline, FewPointsAndNone) {
  EXPECT_FALSE(ConvexOutline().contains({0.0, 0.0}, 1.0));
  const ConvexOutline segment(std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}});
  EXPECT_TRUE(segment.contains({1.0, 0.05}, 0.1));
  EXPECT_FALSE(segment.contains({1.0, 0.2}, 0.1));
}

}  // namespace
}  // namespace meshquilt
