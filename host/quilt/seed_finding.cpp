#include "quilt/seed_finding.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/error.h"

namespace meshquilt {

SeedFinder::SeedFinder(int nx, int ny) : nx_(nx), ny_(ny), unprocessed_(0) {
  if (nx <= 0 || ny <= 0) {
    throw InputError("seed finding: grid size " + std::to_string(nx) + " x " + std::to_string(ny) +
                         " must be positive",
                     ErrorKind::invalid_option);
  }
  const int64_t cells = int64_t(nx) * ny;
  if (cells > int64_t(INT32_MAX) / 2) {
    throw InputError("seed finding: grid of " + std::to_string(cells) + " cells is too large",
                     ErrorKind::invalid_option);
  }
  unprocessed_ = static_cast<int>(cells);
  processed_.assign(cells, 0);
  count_.assign(cells, 0);
  // Every cell starts at priority 0; the heap then yields them in index order.
  heap_.reserve(cells);
  for (int c = 0; c < unprocessed_; ++c) heap_.emplace_back(0, -c);
  std::make_heap(heap_.begin(), heap_.end());
}

SeedFinder::SeedFinder(const std::vector<std::vector<int32_t>>& neighbours)
    : nx_(static_cast<int>(neighbours.size())), ny_(1), unprocessed_(nx_) {
  if (neighbours.empty()) {
    throw InputError("seed finding: the cell graph has no cells", ErrorKind::invalid_option);
  }
  adjacency_offsets_.reserve(neighbours.size() + 1);
  adjacency_offsets_.push_back(0);
  for (size_t c = 0; c < neighbours.size(); ++c) {
    for (int32_t n : neighbours[c]) {
      if (n < 0 || n >= nx_) {
        throw InputError("seed finding: cell " + std::to_string(c) + " lists neighbour " +
                             std::to_string(n) + " outside [0, " + std::to_string(nx_) + ")",
                         ErrorKind::invalid_option);
      }
      adjacency_.push_back(n);
    }
    adjacency_offsets_.push_back(static_cast<int32_t>(adjacency_.size()));
  }
  processed_.assign(neighbours.size(), 0);
  count_.assign(neighbours.size(), 0);
  heap_.reserve(neighbours.size());
  for (int c = 0; c < nx_; ++c) heap_.emplace_back(0, -c);
  std::make_heap(heap_.begin(), heap_.end());
}

template <typename Visit>
void SeedFinder::for_each_neighbour(int cell, Visit&& visit) const {
  if (!adjacency_offsets_.empty()) {
    for (int32_t k = adjacency_offsets_[cell]; k < adjacency_offsets_[cell + 1]; ++k) visit(adjacency_[k]);
    return;
  }
  const int ix = cell % nx_, iy = cell / nx_;
  for (int dy = -1; dy <= 1; ++dy) {
    const int y = iy + dy;
    if (y < 0 || y >= ny_) continue;
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = ix + dx;
      if ((dx == 0 && dy == 0) || x < 0 || x >= nx_) continue;
      visit(y * nx_ + x);
    }
  }
}

void SeedFinder::check_cell(int cell) const {
  if (cell < 0 || cell >= cell_count()) {
    throw std::out_of_range("seed finding: cell " + std::to_string(cell) + " outside [0, " +
                            std::to_string(cell_count()) + ")");
  }
}

void SeedFinder::push(int count, int cell) {
  heap_.emplace_back(count, -cell);
  std::push_heap(heap_.begin(), heap_.end());
}

void SeedFinder::mark_processed(int cell) {
  check_cell(cell);
  if (processed_[cell]) return;
  processed_[cell] = 1;
  --unprocessed_;
  for_each_neighbour(cell, [&](int n) {
    ++count_[n];
    // The older entries of n become stale; next_seed drops them when they surface.
    if (!processed_[n]) push(count_[n], n);
  });
  // A cell's entries outlive its processing; bound the garbage so memory stays O(cells + edges).
  if (heap_.size() > 4 * processed_.size() + 64) {
    std::erase_if(heap_, [&](const std::pair<int, int>& e) {
      return processed_[-e.second] || count_[-e.second] != e.first;
    });
    std::make_heap(heap_.begin(), heap_.end());
  }
}

bool SeedFinder::processed(int cell) const {
  check_cell(cell);
  return processed_[cell] != 0;
}

int SeedFinder::processed_neighbours(int cell) const {
  check_cell(cell);
  return count_[cell];
}

std::optional<int> SeedFinder::next_seed() {
  while (!heap_.empty()) {
    const auto [count, neg_cell] = heap_.front();
    const int cell = -neg_cell;
    // Counts only grow, so an entry whose count differs from the current one is outdated.
    if (!processed_[cell] && count_[cell] == count) return cell;
    std::pop_heap(heap_.begin(), heap_.end());
    heap_.pop_back();
  }
  return std::nullopt;
}

}  // namespace meshquilt
