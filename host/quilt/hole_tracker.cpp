#include "quilt/hole_tracker.h"

#include <algorithm>

#include "core/error.h"

namespace meshquilt {

HoleTracker::HoleTracker(SeedFinder& seeds, int attempts)
    : seeds_(seeds), attempts_(attempts), tries_(seeds.cell_count(), 0), hole_(seeds.cell_count(), 0) {
  if (attempts < 1) throw InputError("seed attempts must be at least 1", ErrorKind::invalid_option);
}

void HoleTracker::attempted(int cell) {
  if (seeds_.processed(cell)) return;
  if (++tries_[cell] < attempts_) return;
  hole_[cell] = 1;
  seeds_.mark_processed(cell);
}

void HoleTracker::give_up(int cell) {
  if (seeds_.processed(cell)) return;
  hole_[cell] = 1;
  seeds_.mark_processed(cell);
}

HoleSummary HoleTracker::summary(const std::vector<std::vector<int32_t>>& neighbours,
                                 const std::vector<double>& cell_areas) const {
  HoleSummary s;
  std::vector<uint8_t> seen(hole_.size(), 0);
  std::vector<int32_t> stack;
  for (size_t start = 0; start < hole_.size(); ++start) {
    if (!hole_[start] || seen[start]) continue;
    int size = 0;
    double area = 0.0;
    seen[start] = 1;
    stack.assign(1, static_cast<int32_t>(start));
    while (!stack.empty()) {
      const int32_t c = stack.back();
      stack.pop_back();
      ++size;
      area += cell_areas.empty() ? 1.0 : cell_areas[c];
      for (int32_t n : neighbours[c])
        if (hole_[n] && !seen[n]) {
          seen[n] = 1;
          stack.push_back(n);
        }
    }
    ++s.holes;
    s.cells += size;
    s.largest_cells = std::max(s.largest_cells, size);
    s.area += area;
    s.largest_area = std::max(s.largest_area, area);
  }
  return s;
}

std::vector<std::vector<int32_t>> grid_neighbours(int nx, int ny) {
  std::vector<std::vector<int32_t>> neighbours(static_cast<size_t>(nx) * ny);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if ((dx || dy) && u >= 0 && v >= 0 && u < nx && v < ny) neighbours[y * nx + x].push_back(v * nx + u);
        }
  return neighbours;
}

}  // namespace meshquilt
