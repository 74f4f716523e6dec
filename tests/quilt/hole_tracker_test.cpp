#include "quilt/hole_tracker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "core/error.h"

namespace meshquilt {
namespace {

TEST(HoleTracker, CellBecomesAHoleAfterItsAttempts) {
  SeedFinder seeds(4, 3);
  HoleTracker tracker(seeds, 3);
  for (int attempt = 1; attempt <= 2; ++attempt) {
    tracker.attempted(5);
    EXPECT_FALSE(seeds.processed(5)) << attempt;
    EXPECT_FALSE(tracker.hole_cells()[5]) << attempt;
  }
  tracker.attempted(5);
  EXPECT_TRUE(seeds.processed(5));
  EXPECT_TRUE(tracker.hole_cells()[5]);
  EXPECT_EQ(seeds.unprocessed_count(), 11);
  // Further attempts change nothing.
  tracker.attempted(5);
  EXPECT_EQ(seeds.unprocessed_count(), 11);
  // A cell covered (processed) before its attempts run out is never a hole.
  tracker.attempted(6);
  seeds.mark_processed(6);
  tracker.attempted(6);
  tracker.attempted(6);
  EXPECT_FALSE(tracker.hole_cells()[6]);
  const auto holes = tracker.hole_cells();
  EXPECT_EQ(std::count(holes.begin(), holes.end(), 1), 1);
}

TEST(HoleTracker, OneAttemptMakesAHoleAtOnce) {
  SeedFinder seeds(2, 2);
  HoleTracker tracker(seeds, 1);
  tracker.attempted(3);
  EXPECT_TRUE(tracker.hole_cells()[3]);
  EXPECT_TRUE(seeds.processed(3));
}

TEST(HoleTracker, GivingUpMakesAHoleBeforeItsAttemptsButNeverOfACoveredCell) {
  SeedFinder seeds(2, 2);
  HoleTracker tracker(seeds, 3);
  tracker.give_up(1);
  EXPECT_TRUE(tracker.hole_cells()[1]);
  EXPECT_TRUE(seeds.processed(1));
  seeds.mark_processed(2);
  tracker.give_up(2);
  EXPECT_FALSE(tracker.hole_cells()[2]);
  EXPECT_EQ(tracker.summary(grid_neighbours(2, 2)).cells, 1);
}

TEST(HoleTracker, AttemptsBelowOneAreRefused) {
  SeedFinder seeds(2, 2);
  try {
    HoleTracker tracker(seeds, 0);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_option);
  }
}

TEST(HoleTracker, SummaryGroupsAdjacentHolesAndSumsAreas) {
  // 6 x 4 grid; holes: {0, 7} (diagonal neighbours: one group), {4, 5, 11} and {21} alone.
  const int nx = 6, ny = 4;
  SeedFinder seeds(nx, ny);
  HoleTracker tracker(seeds, 2);
  for (int cell : {0, 7, 4, 5, 11, 21}) {
    tracker.attempted(cell);
    tracker.attempted(cell);
  }
  const auto neighbours = grid_neighbours(nx, ny);
  HoleSummary s = tracker.summary(neighbours);
  EXPECT_EQ(s.holes, 3);
  EXPECT_EQ(s.cells, 6);
  EXPECT_EQ(s.largest_cells, 3);
  EXPECT_DOUBLE_EQ(s.area, 6.0);
  EXPECT_DOUBLE_EQ(s.largest_area, 3.0);
  // With areas: the lone cell 21 is the largest group by area though not by cells.
  std::vector<double> areas(nx * ny, 0.5);
  areas[21] = 10.0;
  s = tracker.summary(neighbours, areas);
  EXPECT_EQ(s.holes, 3);
  EXPECT_EQ(s.largest_cells, 3);
  EXPECT_DOUBLE_EQ(s.area, 0.5 * 5 + 10.0);
  EXPECT_DOUBLE_EQ(s.largest_area, 10.0);
  // Any cell graph: a chain 0-1-2-3 on four cells, holes at 0, 1 and 3.
  const std::vector<std::vector<int32_t>> chain{{1}, {0, 2}, {1, 3}, {2}};
  SeedFinder chain_seeds(chain);
  HoleTracker chain_tracker(chain_seeds, 1);
  for (int cell : {0, 1, 3}) chain_tracker.attempted(cell);
  s = chain_tracker.summary(chain, {1.0, 2.0, 4.0, 8.0});
  EXPECT_EQ(s.holes, 2);
  EXPECT_EQ(s.cells, 3);
  EXPECT_EQ(s.largest_cells, 2);
  EXPECT_DOUBLE_EQ(s.area, 11.0);
  EXPECT_DOUBLE_EQ(s.largest_area, 8.0);
}

TEST(HoleTracker, NoHolesGiveAnEmptySummary) {
  SeedFinder seeds(3, 3);
  HoleTracker tracker(seeds, 4);
  tracker.attempted(2);
  const HoleSummary s = tracker.summary(grid_neighbours(3, 3));
  EXPECT_EQ(s.holes, 0);
  EXPECT_EQ(s.cells, 0);
  EXPECT_EQ(s.area, 0.0);
}

TEST(GridNeighbours, MatchTheEightNeighbourhood) {
  for (const auto& [nx, ny] : {std::pair{1, 1}, std::pair{5, 1}, std::pair{4, 7}}) {
    const auto neighbours = grid_neighbours(nx, ny);
    ASSERT_EQ(neighbours.size(), static_cast<size_t>(nx * ny));
    for (int c = 0; c < nx * ny; ++c) {
      std::set<int32_t> expected;
      for (int d = 0; d < nx * ny; ++d)
        if (d != c && std::abs(d % nx - c % nx) <= 1 && std::abs(d / nx - c / nx) <= 1) expected.insert(d);
      const std::set<int32_t> got(neighbours[c].begin(), neighbours[c].end());
      EXPECT_EQ(got, expected) << "cell " << c;
      EXPECT_EQ(got.size(), neighbours[c].size()) << "duplicates at cell " << c;
    }
  }
}

}  // namespace
}  // namespace meshquilt
