// Minimum cut: brute force over every SOURCE/SINK assignment of small graphs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "quilt/merging/graph_cut.h"

namespace meshquilt {
namespace {

// Cost of an assignment (bit i set: node i on the SOURCE side); infinite links count as 1e30.
double cut_cost(const CutGraph& g, uint32_t mask) {
  auto cap = [](double c) { return std::isinf(c) ? 1e30 : c; };
  double cost = 0.0;
  for (size_t e = 0; e < g.edges.size(); ++e) {
    const bool a = mask >> g.edges[e][0] & 1, b = mask >> g.edges[e][1] & 1;
    if (a != b) cost += g.weights[e];
  }
  for (int32_t i = 0; i < g.num_nodes; ++i) cost += (mask >> i & 1) ? cap(g.sink_caps[i]) : cap(g.source_caps[i]);
  return cost;
}

double brute_force_min(const CutGraph& g) {
  double best = INFINITY;
  for (uint32_t mask = 0; mask < (1u << g.num_nodes); ++mask) best = std::min(best, cut_cost(g, mask));
  return best;
}

TEST(GraphCut, HandBuiltChainCutsItsWeakestLink) {
  // 0 - 1 - 2 - 3, SOURCE at 0, SINK at 3: the min cut is the lightest edge (1-2, weight 1).
  CutGraph g;
  g.num_nodes = 4;
  g.edges = {{0, 1}, {1, 2}, {2, 3}};
  g.weights = {5.0, 1.0, 3.0};
  g.source_caps = {kInfiniteCapacity, 0, 0, 0};
  g.sink_caps = {0, 0, 0, kInfiniteCapacity};
  const CutResult r = minimum_cut(g);
  EXPECT_DOUBLE_EQ(r.value, 1.0);
  EXPECT_EQ(r.source_side, (std::vector<uint8_t>{1, 1, 0, 0}));
}

TEST(GraphCut, MatchesBruteForceOnRandomTwelveNodeGraphs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> w(0.1, 4.0);
  std::uniform_int_distribution<int> pick(0, 11);
  for (int trial = 0; trial < 40; ++trial) {
    CutGraph g;
    g.num_nodes = 12;
    g.source_caps.assign(12, 0.0);
    g.sink_caps.assign(12, 0.0);
    for (int e = 0; e < 26; ++e) {
      const int a = pick(rng), b = pick(rng);
      if (a == b) continue;
      g.edges.push_back({a, b});
      g.weights.push_back(w(rng));
    }
    // Some infinite terminal links (the paper's forced faces), some finite ones.
    g.source_caps[pick(rng)] = kInfiniteCapacity;
    int s = pick(rng);
    while (std::isinf(g.source_caps[s])) s = pick(rng);
    g.sink_caps[s] = kInfiniteCapacity;
    for (int k = 0; k < 4; ++k) {
      const int i = pick(rng);
      if (!std::isinf(g.source_caps[i]) && !std::isinf(g.sink_caps[i])) (k % 2 ? g.source_caps : g.sink_caps)[i] = w(rng);
    }
    const CutResult r = minimum_cut(g);
    const double best = brute_force_min(g);
    uint32_t mask = 0;
    for (int i = 0; i < 12; ++i) mask |= static_cast<uint32_t>(r.source_side[i]) << i;
    EXPECT_NEAR(r.value, best, 1e-9) << "trial " << trial;
    EXPECT_NEAR(cut_cost(g, mask), best, 1e-9) << "trial " << trial << ": returned sides do not realize the minimum";
    for (int i = 0; i < 12; ++i) {
      if (std::isinf(g.source_caps[i])) EXPECT_EQ(r.source_side[i], 1);
      if (std::isinf(g.sink_caps[i])) EXPECT_EQ(r.source_side[i], 0);
    }
  }
}

TEST(GraphCut, RejectsNodeForcedToBothTerminals) {
  CutGraph g;
  g.num_nodes = 1;
  g.source_caps = {kInfiniteCapacity};
  g.sink_caps = {kInfiniteCapacity};
  EXPECT_THROW(minimum_cut(g), InputError);
  g.sink_caps = {-1.0};
  EXPECT_THROW(minimum_cut(g), InputError);
}

}  // namespace
}  // namespace meshquilt
