#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "core/error.h"
#include "loom/block_assignment.h"
#include "loom_designs.h"

namespace meshquilt {
namespace {

// Pattern p tiled over `warps` x `wefts` crossings.
WeavePattern tiled(const WeavePattern& p, int warps, int wefts) {
  WeavePattern out{warps, wefts, {}};
  for (int j = 0; j < wefts; ++j)
    for (int i = 0; i < warps; ++i) out.warp_over.push_back(p.over(i, j) ? 1 : 0);
  return out;
}

LoomDesign random_design(int rows, int columns, std::mt19937& rng) {
  LoomDesign d{rows, columns, {}};
  for (int k = 0; k < rows * columns; ++k) d.warp_over.push_back(static_cast<uint8_t>(rng() & 1));
  return d;
}

// The most neighbours any interior block of the exemplars can match at (r, c), by brute force.
int best_consistency(const LoomDesign& d, const std::vector<WeavePattern>& ex, int r, int c) {
  const int dr[4] = {-1, 1, 0, 0}, dc[4] = {0, 0, -1, 1};
  int best = -1;
  for (const WeavePattern& p : ex)
    for (int y = 1; y + 1 < p.wefts; ++y)
      for (int x = 1; x + 1 < p.warps; ++x) {
        if (p.over(x, y) != d.at(r, c)) continue;
        int m = 0;
        for (int k = 0; k < 4; ++k) {
          const int rr = r + dr[k], cc = c + dc[k];
          if (rr >= 0 && rr < d.rows && cc >= 0 && cc < d.columns) m += p.over(x + dc[k], y - dr[k]) == d.at(rr, cc);
        }
        best = std::max(best, m);
      }
  return best;
}

int consistency(const LoomDesign& d, const std::vector<WeavePattern>& ex, const LoomBlock& b, int r, int c) {
  const int dr[4] = {-1, 1, 0, 0}, dc[4] = {0, 0, -1, 1};
  int m = 0;
  for (int k = 0; k < 4; ++k) {
    const int rr = r + dr[k], cc = c + dc[k];
    if (rr >= 0 && rr < d.rows && cc >= 0 && cc < d.columns)
      m += ex[b.exemplar].over(b.x + dc[k], b.y - dr[k]) == d.at(rr, cc);
  }
  return m;
}

const std::vector<WeavePattern> kExemplars = {tiled(twill_pattern(1, 1), 6, 6), tiled(twill_pattern(2, 2), 8, 8),
                                              tiled(satin_pattern(5, 2), 10, 10)};

TEST(BlockAssignment, EveryCrossingTakesTheCorrectYarnAndTheMostConsistentBlock) {
  std::mt19937 rng(7);
  for (AssignmentMethod method : {AssignmentMethod::greedy, AssignmentMethod::structured}) {
    const LoomDesign d = random_design(17, 13, rng);
    AssignmentOptions options;
    options.method = method;
    const LoomAssignment a = assign_blocks(d, kExemplars, options);
    for (int r = 0; r < d.rows; ++r)
      for (int c = 0; c < d.columns; ++c) {
        const LoomBlock& b = a.at(r, c);
        const WeavePattern& p = kExemplars[b.exemplar];
        ASSERT_TRUE(b.x >= 1 && b.y >= 1 && b.x + 1 < p.warps && b.y + 1 < p.wefts);
        EXPECT_EQ(p.over(b.x, b.y), d.at(r, c));
        EXPECT_EQ(consistency(d, kExemplars, b, r, c), best_consistency(d, kExemplars, r, c)) << r << ", " << c;
      }
  }
}

// Along one warp, the dynamic programme's continuity equals the best of every chain of most
// consistent blocks (enumerated), with randomization over the whole design at once.
TEST(BlockAssignment, ContinuityAlongAWarpIsTheBestAnyChainReaches) {
  std::mt19937 rng(3);
  const std::vector<WeavePattern> ex = {tiled(twill_pattern(1, 1), 5, 5), tiled(twill_pattern(2, 1), 6, 6)};
  for (int trial = 0; trial < 20; ++trial) {
    const LoomDesign d = random_design(6, 3, rng);
    AssignmentOptions options;
    options.seed = static_cast<uint64_t>(trial);
    options.shift_block = 1 << 20;
    const LoomAssignment a = assign_blocks(d, ex, options);
    const int c = 1;
    // Brute force: every chain of blocks reaching the best consistency at each row.
    std::vector<std::vector<LoomBlock>> choices(static_cast<size_t>(d.rows));
    for (int r = 0; r < d.rows; ++r)
      for (size_t u = 0; u < ex.size(); ++u)
        for (int y = 1; y + 1 < ex[u].wefts; ++y)
          for (int x = 1; x + 1 < ex[u].warps; ++x) {
            const LoomBlock b{static_cast<int32_t>(u), x, y};
            if (ex[u].over(x, y) == d.at(r, c) &&
                consistency(d, ex, b, r, c) == best_consistency(d, ex, r, c))
              choices[r].push_back(b);
          }
    int best = 0;
    std::vector<LoomBlock> chain(static_cast<size_t>(d.rows));
    std::function<void(int, int)> walk = [&](int r, int links) {
      if (r == d.rows) {
        best = std::max(best, links);
        return;
      }
      for (const LoomBlock& b : choices[r]) {
        chain[r] = b;
        const bool link = r > 0 && chain[r - 1].exemplar == b.exemplar && chain[r - 1].x == b.x && chain[r - 1].y == b.y + 1;
        walk(r + 1, links + (link ? 1 : 0));
      }
    };
    walk(0, 0);
    int found = 0;
    for (int r = 1; r < d.rows; ++r) {
      const LoomBlock &up = a.at(r - 1, c), &b = a.at(r, c);
      found += up.exemplar == b.exemplar && up.x == b.x && up.y == b.y + 1;
    }
    EXPECT_EQ(found, best) << "trial " << trial;
  }
}

TEST(BlockAssignment, StructuredBeatsGreedyAndGreedyBeatsNaive) {
  const LoomDesign d = three_regions(96);
  AssignmentScores scores[3];
  for (int m = 0; m < 3; ++m) {
    AssignmentOptions options;
    options.method = static_cast<AssignmentMethod>(m);
    scores[m] = score_assignment(d, kExemplars, assign_blocks(d, kExemplars, options));
    EXPECT_EQ(scores[m].correct, 1.0);
  }
  const AssignmentScores &naive = scores[0], &greedy = scores[1], &ours = scores[2];
  EXPECT_GT(greedy.consistent, naive.consistent + 0.2);
  EXPECT_EQ(ours.consistent, greedy.consistent);
  EXPECT_GT(ours.consistent, 0.97);  // only the regions' seams hold inconsistent crossings
  EXPECT_GT(ours.continuous_along_warps, greedy.continuous_along_warps + 0.3);
  EXPECT_GT(ours.continuous, 0.5);
}

TEST(BlockAssignment, RefusesADesignTheExemplarsCannotWeave) {
  const std::vector<WeavePattern> weft_only = {WeavePattern{4, 4, std::vector<uint8_t>(16, 0)}};
  LoomDesign d{2, 2, {0, 1, 0, 0}};
  EXPECT_THROW(assign_blocks(d, weft_only), InputError);
  d.warp_over = {0, 0, 0, 0};
  EXPECT_NO_THROW(assign_blocks(d, weft_only));
}

}  // namespace
}  // namespace meshquilt
