#pragma once
//! Seed finding (Section 2.3 of the mesh quilting paper): the next unprocessed cell of a 2D grid
//! with the most processed 8-neighbours, kept in a priority structure (O(log n) per step).

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace meshquilt {

//! Picks seed cells in the order of Section 2.3: always the unprocessed cell with the most
//! processed neighbours, ties to the lowest cell index. A binary max-heap over
//! (neighbour count, -cell) with lazy deletion: mark_processed pushes one entry per raised
//! neighbour, next_seed discards stale entries, so both are O(log n) amortized.
class SeedFinder {
 public:
  //! A grid of nx x ny cells, all unprocessed, with the 8-neighbourhood. Cell index = iy * nx + ix.
  //! \throw InputError (invalid_option) when nx or ny is not positive.
  SeedFinder(int nx, int ny);

  //! Any cell graph (e.g. the triangles of a base mesh, Section 3.1): `neighbours[c]` lists the
  //! cells adjacent to cell c (#cells lists; indices in range; symmetric, no self loops, no
  //! duplicates). nx() is then the cell count and ny() is 1.
  //! \throw InputError (invalid_option) when the list is empty or an index is out of range.
  explicit SeedFinder(const std::vector<std::vector<int32_t>>& neighbours);

  //! Marks a cell processed (idempotent) and raises its unprocessed neighbours' priority.
  //! \throw std::out_of_range for a cell outside [0, cell_count()).
  void mark_processed(int cell);
  //! \throw std::out_of_range for a cell outside [0, cell_count()).
  bool processed(int cell) const;

  //! The unprocessed cell with the most processed neighbours; ties go to the lowest cell index
  //! (cell 0 before anything is processed). std::nullopt when every cell is processed.
  //! Does not mark the cell: calling it twice without mark_processed returns the same cell.
  std::optional<int> next_seed();

  //! Processed neighbours of a cell (its priority).
  int processed_neighbours(int cell) const;

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int cell_count() const { return static_cast<int>(processed_.size()); }
  int unprocessed_count() const { return unprocessed_; }

 private:
  template <typename Visit>
  void for_each_neighbour(int cell, Visit&& visit) const;
  void push(int count, int cell);
  void check_cell(int cell) const;

  int nx_, ny_, unprocessed_;
  std::vector<uint8_t> processed_;
  std::vector<int32_t> count_;
  // Cell graph in compressed rows; empty for the implicit 8-neighbourhood grid.
  std::vector<int32_t> adjacency_offsets_;
  std::vector<int32_t> adjacency_;
  std::vector<std::pair<int, int>> heap_;  // (count, -cell), max-heap, lazy deletion
};

}  // namespace meshquilt
