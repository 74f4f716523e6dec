#pragma once
//! Seed finding (Section 2.3 of the mesh quilting paper): the next unprocessed cell of a 2D grid
//! with the most processed 8-neighbours, kept in a priority structure (O(log n) per step).

#include <cstdint>
#include <optional>
#include <vector>

namespace meshquilt {

class SeedFinder {
 public:
  //! A grid of nx x ny cells, all unprocessed. Cell index = iy * nx + ix.
  SeedFinder(int nx, int ny);

  //! Marks a cell processed (idempotent) and raises its unprocessed neighbours' priority.
  void mark_processed(int cell);
  bool processed(int cell) const;

  //! The unprocessed cell with the most processed neighbours; ties go to the lowest cell index.
  //! std::nullopt when every cell is processed.
  std::optional<int> next_seed();

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int unprocessed_count() const { return unprocessed_; }

 private:
  // Implementation-defined members (priority structure over (neighbour count, -index)).
  int nx_, ny_, unprocessed_;
  std::vector<uint8_t> processed_;
  std::vector<uint8_t> count_;
  struct Queue;
  std::vector<std::pair<int, int>> heap_;  // (count, -cell), lazy deletion
};

}  // namespace meshquilt
