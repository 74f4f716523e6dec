#pragma once
//! Holes: cells that stay uncovered after a few patches seeded on them are given up on (marked
//! processed so synthesis ends) and counted, never left silently.

#include <cstdint>
#include <vector>

#include "quilt/seed_finding.h"

namespace meshquilt {

struct HoleSummary {
  int holes = 0;          //!< connected groups of hole cells
  int cells = 0;          //!< hole cells
  int largest_cells = 0;  //!< cells in the largest group
  double area = 0.0;          //!< summed cell areas of all hole cells
  double largest_area = 0.0;  //!< area of the largest group (by area)
};

//! Counts the patches seeded on each cell and gives up on a cell after `attempts` of them.
class HoleTracker {
 public:
  //! \throw InputError (invalid_option) for attempts < 1.
  HoleTracker(SeedFinder& seeds, int attempts);

  //! Records a patch seeded on `cell`; when the cell is still unprocessed after the allowed
  //! number of attempts it becomes a hole and is marked processed.
  void attempted(int cell);

  //! Makes `cell` a hole now, marked processed: for a patch that would come out the same again.
  void give_up(int cell);

  //! Hole cells grouped by `neighbours` (#cells adjacency lists, as for SeedFinder); areas from
  //! `cell_areas` (#cells), or 1 per cell when it is empty.
  HoleSummary summary(const std::vector<std::vector<int32_t>>& neighbours,
                      const std::vector<double>& cell_areas = {}) const;

  const std::vector<uint8_t>& hole_cells() const { return hole_; }
  //! Patches seeded on `cell` so far.
  int tries(int cell) const { return tries_[cell]; }

 private:
  SeedFinder& seeds_;
  int attempts_;
  std::vector<int32_t> tries_;
  std::vector<uint8_t> hole_;
};

//! 8-neighbourhood adjacency lists of an nx x ny grid (cell = y * nx + x).
std::vector<std::vector<int32_t>> grid_neighbours(int nx, int ny);

}  // namespace meshquilt
