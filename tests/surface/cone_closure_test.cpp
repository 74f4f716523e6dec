// The closure's plan over a European 4-in-1 sheet built here from circles: columns of rings
// leaning alternately, each linked to the two nearest rings of each neighbouring column.

#include "surface/cone_closure.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace meshquilt {
namespace {

constexpr double kColumn = 1.2, kRow = 1.0, kLean = 0.6, kWire = 0.08;

// A unit circle in the plane of x and (0, cos lean, +-sin lean), turned by `turn` about z.
ClosureRing circle(double x, double y, int lean, double turn = 0.0) {
  std::vector<Vec3> line;
  for (int k = 0; k < 24; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 24.0;
    const Vec3 p(std::cos(t), std::sin(t) * std::cos(kLean), lean * std::sin(t) * std::sin(kLean));
    line.emplace_back(x + std::cos(turn) * p.x - std::sin(turn) * p.y, y + std::sin(turn) * p.x + std::cos(turn) * p.y, p.z);
  }
  return closure_ring(std::move(line));
}

// Ring (j, k) of the sheet: column j, row k.
ClosureRing sheet_ring(int j, int k) {
  return circle(j * kColumn, k * kRow + (j % 2 != 0 ? 0.5 * kRow : 0.0), j % 2 == 0 ? 1 : -1);
}

struct Sheet {
  std::vector<ClosureRing> rings;
  std::vector<uint8_t> core;
  std::map<std::pair<int, int>, int32_t> index;
};

// Columns and rows -4..4 less those left out; the core within 2.5 of the origin.
Sheet sheet(const std::vector<std::pair<int, int>>& left_out = {}) {
  Sheet s;
  for (int j = -4; j <= 4; ++j)
    for (int k = -4; k <= 4; ++k) {
      if (std::find(left_out.begin(), left_out.end(), std::make_pair(j, k)) != left_out.end()) continue;
      s.index[{j, k}] = static_cast<int32_t>(s.rings.size());
      s.rings.push_back(sheet_ring(j, k));
      s.core.push_back(glm::length(s.rings.back().centre) < 2.5);
    }
  return s;
}

ClosureCandidates given(std::vector<ClosureRing> candidates) {
  return [candidates = std::move(candidates)](const std::vector<uint8_t>&) { return candidates; };
}

ClosureOptions options() {
  ClosureOptions o;
  o.links = 4;
  o.clearance = 2.0 * kWire;
  return o;
}

TEST(ConeClosure, TheSheetLinksEachRingToFourAndNothingMeets) {
  const Sheet s = sheet();
  // Nothing to take out, and no place for another ring.
  const ClosurePlan plan = plan_closure(s.rings, s.core, given({circle(0.0, 0.0, -1, 0.5 * std::numbers::pi)}), options());
  EXPECT_TRUE(plan.removed.empty());
  EXPECT_TRUE(plan.added.empty());
  EXPECT_EQ(plan.short_before, 0);
  EXPECT_EQ(plan.short_after, 0);
}

TEST(ConeClosure, OneRingMissingLeavesFourLinkedToThreeAsAMailClosesRoundAPoint) {
  const Sheet s = sheet({{0, 0}});
  const ClosurePlan plan = plan_closure(s.rings, s.core, given({sheet_ring(0, 0)}), options());
  EXPECT_TRUE(plan.removed.empty());
  EXPECT_TRUE(plan.added.empty());
  EXPECT_EQ(plan.short_before, 0);
}

TEST(ConeClosure, ARingLeftWithTwoLinksGetsTheRingThatLinksItAndTwoOthers) {
  // Ring (-1, 0) keeps two links of four.
  const Sheet s = sheet({{0, 0}, {1, 0}, {0, 1}});
  // Rings at the hole leaning the wrong way, turned across it, off the lattice, far away, and
  // two of those missing.
  const std::vector<ClosureRing> candidates = {circle(0.0, 0.0, -1),  circle(0.0, 0.0, 1, 0.5 * std::numbers::pi),
                                               circle(0.3, 0.2, 1),   circle(5.0, 5.0, 1),
                                               sheet_ring(0, 0),      sheet_ring(0, 1)};
  const ClosurePlan plan = plan_closure(s.rings, s.core, given(candidates), options());
  EXPECT_TRUE(plan.removed.empty());
  EXPECT_EQ(plan.short_before, 1);
  EXPECT_EQ(plan.short_after, 0);
  // Either missing ring links (-1, 0) and two rings under four; one is enough.
  ASSERT_EQ(plan.added.size(), 1u);
  EXPECT_TRUE(plan.added[0] == 4 || plan.added[0] == 5);
}

TEST(ConeClosure, ARingThroughTheSheetIsTakenOutAndNotItsNeighbours) {
  Sheet s = sheet();
  s.rings.push_back(circle(0.6, 0.25, 1, 0.5 * std::numbers::pi));
  s.core.push_back(1);
  const ClosurePlan plan = plan_closure(s.rings, s.core, given({}), options());
  ASSERT_EQ(plan.removed.size(), 1u);
  EXPECT_EQ(plan.removed[0], static_cast<int32_t>(s.rings.size() - 1));
  EXPECT_GT(plan.short_before, 0);
  EXPECT_EQ(plan.short_after, 0);
}

TEST(ConeClosure, ARingThatWouldLinkNoShortRingIsNotAdded) {
  // One of the hole's four neighbours lies in the core: one short ring is not enough to add one.
  Sheet s = sheet({{3, 0}});
  const ClosurePlan plan = plan_closure(s.rings, s.core, given({sheet_ring(3, 0)}), options());
  EXPECT_TRUE(plan.added.empty());
}

TEST(ConeClosure, CentreLineDistanceOfTwoParallelSquares) {
  const std::vector<Vec3> a = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<Vec3> b = a;
  for (Vec3& p : b) p += Vec3(0.5, 0.5, 0.25);
  EXPECT_NEAR(centre_line_distance(a, b), 0.25, 1e-12);
  for (Vec3& p : b) p += Vec3(2.0, 0.0, 0.0);
  EXPECT_NEAR(centre_line_distance(a, b), std::sqrt(1.5 * 1.5 + 0.25 * 0.25), 1e-12);
}

}  // namespace
}  // namespace meshquilt
