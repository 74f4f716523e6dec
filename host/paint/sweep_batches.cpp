#include "paint/sweep_batches.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace meshquilt {

WindowNeighbours window_neighbours(const BaseSurface& surface, double radius) {
  const size_t n = surface.mesh.num_vertices();
  WindowNeighbours out;
  out.first.reserve(n + 1);
  out.first.push_back(0);
  std::vector<uint32_t> seen(n, 0);
  std::vector<int32_t> frontier;
  for (size_t v = 0; v < n; ++v) {
    const uint32_t stamp = static_cast<uint32_t>(v) + 1;
    const Vec3& p = surface.mesh.positions[v];
    frontier.assign(1, static_cast<int32_t>(v));
    seen[v] = stamp;
    for (size_t k = 0; k < frontier.size(); ++k)
      for (const auto& [w, length] : surface.edges[frontier[k]]) {
        (void)length;
        if (seen[w] == stamp) continue;
        seen[w] = stamp;
        if (glm::length(surface.mesh.positions[w] - p) > radius) continue;
        frontier.push_back(w);
        out.vertices.push_back(w);
      }
    out.first.push_back(static_cast<int64_t>(out.vertices.size()));
  }
  return out;
}

std::vector<std::vector<int32_t>> sweep_batches(const std::vector<int32_t>& order, const WindowNeighbours& windows,
                                                size_t max_batch) {
  std::vector<std::vector<int32_t>> batches;
  if (max_batch <= 1) {
    for (int32_t v : order) batches.push_back({v});
    return batches;
  }
  const size_t n = order.size();
  std::vector<int32_t> position(n);
  for (size_t k = 0; k < n; ++k) position[order[k]] = static_cast<int32_t>(k);
  // level[v]: after every earlier vertex v reads; floor[v]: not before an earlier vertex that
  // reads v (the same batch is fine: that vertex sees v's old state either way).
  std::vector<int32_t> level(n, 0), floor(n, 0);
  int32_t levels = 0;
  for (int32_t v : order) {
    int32_t l = floor[v];
    for (int64_t k = windows.first[v]; k < windows.first[v + 1]; ++k) {
      const int32_t u = windows.vertices[k];
      if (position[u] < position[v]) l = std::max(l, level[u] + 1);
    }
    level[v] = l;
    levels = std::max(levels, l + 1);
    for (int64_t k = windows.first[v]; k < windows.first[v + 1]; ++k) {
      const int32_t w = windows.vertices[k];
      if (position[w] > position[v]) floor[w] = std::max(floor[w], l);
    }
  }
  std::vector<std::vector<int32_t>> by_level(levels);
  for (int32_t v : order) by_level[level[v]].push_back(v);
  for (std::vector<int32_t>& batch : by_level)
    for (size_t first = 0; first < batch.size(); first += max_batch)
      batches.emplace_back(batch.begin() + static_cast<std::ptrdiff_t>(first),
                           batch.begin() + static_cast<std::ptrdiff_t>(std::min(batch.size(), first + max_batch)));
  return batches;
}

}  // namespace meshquilt
