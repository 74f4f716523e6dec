#pragma once
//! A uniform grid of cubic cells hashed into a map: the one spatial hash of meshquilt, a broad
//! phase for "which items lie near this point or box".

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Hash of the integer grid cell (i, j, k), with the primes of Teschner et al. 2003 ("Optimized
//! spatial hashing for collision detection of deformable objects"). Distinct cells may collide;
//! a grid keyed by it must check candidates exactly.
inline uint64_t grid_cell_hash(int64_t i, int64_t j, int64_t k) {
  return static_cast<uint64_t>((i * 73856093) ^ (j * 19349663) ^ (k * 83492791));
}

//! Items (int32 ids) listed in every cell of side `cell` that their axis-aligned box touches.
//! Cells whose hashes collide share one list, so a lookup may return extra items (never fewer).
class BoxGrid {
 public:
  //! \pre cell > 0.
  explicit BoxGrid(double cell) : cell_(cell) {}

  //! The cell coordinate of x along any axis: floor(x / cell).
  int64_t cell_of(double x) const { return static_cast<int64_t>(std::floor(x / cell_)); }

  //! Lists `item` in every cell touched by the box [lo, hi].
  void insert(int32_t item, const Vec3& lo, const Vec3& hi) {
    for_each_cell_key(lo, hi, [&](uint64_t key) { cells_[key].push_back(item); });
  }

  //! The items listed in the cell holding p (in insertion order), or nullptr when none are.
  const std::vector<int32_t>* items_at(const Vec3& p) const {
    const auto it = cells_.find(grid_cell_hash(cell_of(p.x), cell_of(p.y), cell_of(p.z)));
    return it == cells_.end() ? nullptr : &it->second;
  }

  //! Calls visit(items) for each non-empty cell touched by the box [lo, hi], x outermost; an item
  //! spanning several cells is visited once per cell.
  template <class Visit>
  void for_each_cell(const Vec3& lo, const Vec3& hi, Visit&& visit) const {
    for_each_cell_key(lo, hi, [&](uint64_t key) {
      const auto it = cells_.find(key);
      if (it != cells_.end()) visit(it->second);
    });
  }

 private:
  template <class Visit>
  void for_each_cell_key(const Vec3& lo, const Vec3& hi, Visit&& visit) const {
    for (int64_t i = cell_of(lo.x); i <= cell_of(hi.x); ++i)
      for (int64_t j = cell_of(lo.y); j <= cell_of(hi.y); ++j)
        for (int64_t k = cell_of(lo.z); k <= cell_of(hi.z); ++k) visit(grid_cell_hash(i, j, k));
  }

  double cell_;
  std::unordered_map<uint64_t, std::vector<int32_t>> cells_;
};

}  // namespace meshquilt
