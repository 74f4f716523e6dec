#include "quilt/merging/seam_alignment.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "spatial/segment_distance.h"

namespace meshquilt {

Alignment align_loops(const std::vector<Vec3>& first, const std::vector<Vec3>& second, double min_split) {
  const int32_t m = static_cast<int32_t>(first.size()), n = static_cast<int32_t>(second.size());
  const double inf = std::numeric_limits<double>::infinity();
  const int32_t stride = n + 1;  // cost[i * stride + j]: first i points and second j points placed
  std::vector<double> cost(static_cast<size_t>(m + 1) * stride, inf);
  enum Step : uint8_t { none, both, first_only, second_only };
  std::vector<uint8_t> from(static_cast<size_t>(m + 1) * stride, none);
  // A point landing near an end of the other edge would create a sliver, so the split stays
  // within [min_split, 1 - min_split] of the edge and pays for the distance to that point.
  auto alone_cost = [&](const Vec3& x, const Vec3& a, const Vec3& b, double* lambda) {
    point_segment_distance(x, a, b, lambda);
    *lambda = std::clamp(*lambda, min_split, 1.0 - min_split);
    return glm::length(x - glm::mix(a, b, *lambda));
  };
  cost[1 * stride + 1] = glm::length(first[0] - second[0]);
  for (int32_t i = 1; i <= m; ++i) {
    for (int32_t j = 1; j <= n; ++j) {
      if (i == 1 && j == 1) continue;
      double best = inf;
      uint8_t how = none;
      if (i >= 2 && j >= 2) {
        const double c = cost[(i - 1) * stride + (j - 1)] + glm::length(first[i - 1] - second[j - 1]);
        if (c < best) best = c, how = both;
      }
      if (i >= 2) {
        double lambda;
        const double c = cost[(i - 1) * stride + j] + alone_cost(first[i - 1], second[j - 1], second[j % n], &lambda);
        if (c < best) best = c, how = first_only;
      }
      if (j >= 2) {
        double lambda;
        const double c = cost[i * stride + (j - 1)] + alone_cost(second[j - 1], first[i - 1], first[i % m], &lambda);
        if (c < best) best = c, how = second_only;
      }
      cost[i * stride + j] = best;
      from[i * stride + j] = how;
    }
  }
  Alignment out;
  out.cost = cost[m * stride + n];
  int32_t i = m, j = n;
  while (!(i == 1 && j == 1)) {
    SeamEvent e;
    switch (from[i * stride + j]) {
      case both: e.kind = SeamEvent::pair, e.first = i - 1, e.second = j - 1, --i, --j; break;
      case first_only:
        e.kind = SeamEvent::first_alone, e.first = i - 1, e.seg0 = j - 1, e.seg1 = j % n;
        alone_cost(first[i - 1], second[j - 1], second[j % n], &e.lambda);
        --i;
        break;
      case second_only:
        e.kind = SeamEvent::second_alone, e.second = j - 1, e.seg0 = i - 1, e.seg1 = i % m;
        alone_cost(second[j - 1], first[i - 1], first[i % m], &e.lambda);
        --j;
        break;
      default: out.cost = inf; return out;
    }
    out.events.push_back(e);
  }
  out.events.push_back(SeamEvent{SeamEvent::pair, 0, 0, -1, -1, 0.0});
  std::reverse(out.events.begin(), out.events.end());
  // Points splitting the same edge form a run in seam order; their split parameters must rise
  // by at least min_split, or they are spread evenly along the edge.
  for (size_t r = 0; r < out.events.size();) {
    size_t s = r + 1;
    if (out.events[r].kind != SeamEvent::pair)
      while (s < out.events.size() && out.events[s].kind == out.events[r].kind && out.events[s].seg0 == out.events[r].seg0) ++s;
    bool spaced = true;
    for (size_t t = r + 1; t < s; ++t) spaced = spaced && out.events[t].lambda - out.events[t - 1].lambda >= min_split;
    if (!spaced)
      for (size_t t = r; t < s; ++t) out.events[t].lambda = static_cast<double>(t - r + 1) / static_cast<double>(s - r + 1);
    r = s;
  }
  return out;
}

}  // namespace meshquilt
