#include "quilt/seed_finding.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "core/error.h"

namespace meshquilt {
namespace {

// Reference: a full scan that recounts every cell's processed 8-neighbours from scratch.
std::optional<int> brute_force_seed(int nx, int ny, const std::vector<bool>& done) {
  std::optional<int> best;
  int best_count = -1;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const int cell = iy * nx + ix;
      if (done[cell]) continue;
      int count = 0;
      for (int y = iy - 1; y <= iy + 1; ++y)
        for (int x = ix - 1; x <= ix + 1; ++x)
          if ((x != ix || y != iy) && x >= 0 && y >= 0 && x < nx && y < ny && done[y * nx + x]) ++count;
      if (count > best_count) {  // strict: the first (lowest) index wins ties
        best_count = count;
        best = cell;
      }
    }
  }
  return best;
}

TEST(SeedFinder, FirstSeedIsCellZero) {
  SeedFinder finder(5, 4);
  EXPECT_EQ(finder.next_seed(), 0);
  EXPECT_EQ(finder.next_seed(), 0);  // next_seed does not consume
  EXPECT_EQ(finder.unprocessed_count(), 20);
}

TEST(SeedFinder, ExactCountsOnConstructedGrid) {
  // 4 x 4 grid; process the centre-ish cell 5 (ix=1, iy=1): all 8 neighbours get count 1.
  SeedFinder finder(4, 4);
  finder.mark_processed(5);
  const std::set<int> ring = {0, 1, 2, 4, 6, 8, 9, 10};
  for (int c = 0; c < 16; ++c) {
    EXPECT_EQ(finder.processed_neighbours(c), ring.count(c) ? 1 : 0) << c;
  }
  EXPECT_EQ(finder.next_seed(), 0);  // ties among count 1: lowest index
  // Processing 10 (ix=2, iy=2) raises 5's ring overlap {6, 9} to 2, and adds 11, 14, 15 (count 1).
  finder.mark_processed(10);
  EXPECT_EQ(finder.processed_neighbours(6), 2);
  EXPECT_EQ(finder.processed_neighbours(9), 2);
  EXPECT_EQ(finder.processed_neighbours(15), 1);
  EXPECT_EQ(finder.processed_neighbours(3), 0);
  EXPECT_EQ(finder.next_seed(), 6);
  finder.mark_processed(6);
  // 6 = (2,1) and 9 = (1,2) are diagonal neighbours: 9 now has 5, 6 and 10 processed.
  EXPECT_EQ(finder.processed_neighbours(9), 3);
  EXPECT_EQ(finder.next_seed(), 9);
  // Corner cell 0 has 3 neighbours at most; edge cell 1 has 5.
  SeedFinder corner(3, 3);
  for (int c : {1, 3, 4}) corner.mark_processed(c);
  EXPECT_EQ(corner.processed_neighbours(0), 3);
  EXPECT_EQ(corner.next_seed(), 0);
  EXPECT_EQ(corner.unprocessed_count(), 6);
}

TEST(SeedFinder, MarkProcessedIsIdempotent) {
  SeedFinder finder(3, 3);
  finder.mark_processed(4);
  finder.mark_processed(4);
  EXPECT_EQ(finder.unprocessed_count(), 8);
  EXPECT_EQ(finder.processed_neighbours(0), 1);
  EXPECT_TRUE(finder.processed(4));
  EXPECT_FALSE(finder.processed(0));
}

TEST(SeedFinder, MatchesFullScanOnRandomSequences) {
  std::mt19937 rng(1234);
  for (int trial = 0; trial < 40; ++trial) {
    const int nx = 1 + int(rng() % 23), ny = 1 + int(rng() % 17);
    SeedFinder finder(nx, ny);
    std::vector<bool> done(nx * ny, false);
    int steps = 0;
    while (true) {
      const std::optional<int> expected = brute_force_seed(nx, ny, done);
      ASSERT_EQ(finder.next_seed(), expected) << "trial " << trial << " step " << steps;
      if (!expected) break;
      // Mostly follow the seed, sometimes mark a random cell (processed or not), as geometry
      // matching marks several cells under a patch.
      const int r = int(rng() % 4);
      const int cell = r == 0 ? int(rng() % (nx * ny)) : *expected;
      finder.mark_processed(cell);
      done[cell] = true;
      if (r == 1) {  // a block of cells around the seed
        const int ix = cell % nx, iy = cell / nx;
        for (int y = iy - 1; y <= iy + 1; ++y)
          for (int x = ix; x <= ix + 2; ++x)
            if (x < nx && y >= 0 && y < ny) {
              finder.mark_processed(y * nx + x);
              done[y * nx + x] = true;
            }
      }
      int unprocessed = 0;
      for (bool d : done) unprocessed += !d;
      ASSERT_EQ(finder.unprocessed_count(), unprocessed);
      ++steps;
    }
    EXPECT_EQ(finder.unprocessed_count(), 0);
    EXPECT_LE(steps, nx * ny);  // terminates: every step processes at least one cell
  }
}

TEST(SeedFinder, TerminatesFollowingSeedsOnly) {
  SeedFinder finder(37, 29);
  int steps = 0;
  std::vector<int> order;
  while (auto seed = finder.next_seed()) {
    ASSERT_FALSE(finder.processed(*seed));
    finder.mark_processed(*seed);
    order.push_back(*seed);
    ASSERT_LE(++steps, 37 * 29);
  }
  EXPECT_EQ(steps, 37 * 29);
  EXPECT_EQ(std::set<int>(order.begin(), order.end()).size(), size_t(37 * 29));
  EXPECT_FALSE(finder.next_seed().has_value());
  // Following seeds grows the processed region from cell 0: the second seed is its neighbour 1.
  EXPECT_EQ(order[0], 0);
  EXPECT_EQ(order[1], 1);
}

TEST(SeedFinder, GraphCellsMatchFullScan) {
  std::mt19937 rng(99);
  const int n = 200;
  std::vector<std::set<int32_t>> sets(n);
  for (int e = 0; e < 600; ++e) {
    const int a = int(rng() % n), b = int(rng() % n);
    if (a == b) continue;
    sets[a].insert(b);
    sets[b].insert(a);
  }
  std::vector<std::vector<int32_t>> neighbours(n);
  for (int c = 0; c < n; ++c) neighbours[c].assign(sets[c].begin(), sets[c].end());
  SeedFinder finder(neighbours);
  std::vector<bool> done(n, false);
  while (true) {
    std::optional<int> expected;
    int best = -1;
    for (int c = 0; c < n; ++c) {
      if (done[c]) continue;
      int count = 0;
      for (int32_t m : neighbours[c]) count += done[m];
      if (count > best) best = count, expected = c;
    }
    ASSERT_EQ(finder.next_seed(), expected);
    if (!expected) break;
    const int cell = rng() % 3 == 0 ? int(rng() % n) : *expected;
    finder.mark_processed(cell);
    done[cell] = true;
  }
}

TEST(SeedFinder, RejectsBadInput) {
  EXPECT_THROW(SeedFinder(0, 3), InputError);
  EXPECT_THROW(SeedFinder(3, -1), InputError);
  EXPECT_THROW(SeedFinder(std::vector<std::vector<int32_t>>{{1}, {5}}), InputError);
  SeedFinder finder(2, 2);
  EXPECT_THROW(finder.mark_processed(4), std::out_of_range);
  EXPECT_THROW(finder.mark_processed(-1), std::out_of_range);
}

}  // namespace
}  // namespace meshquilt
