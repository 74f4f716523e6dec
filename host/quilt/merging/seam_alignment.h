#pragma once
//! Dynamic-programming alignment of two closed seam polylines (Section 2.7 of the mesh quilting
//! paper, after Yu et al. 2004): which points weld together and which split the other loop's
//! edge.

#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! One seam point of an aligned loop pair: a first-loop vertex welded to a second-loop vertex, or
//! one of them splitting the other loop's edge (seg0 -> seg1 in seam order) at `lambda`.
struct SeamEvent {
  enum Kind : uint8_t { pair, first_alone, second_alone } kind = pair;
  int32_t first = -1, second = -1;  // loop positions (first loop; second loop as aligned, see Alignment)
  int32_t seg0 = -1, seg1 = -1;     // other loop's edge ends, loop positions
  double lambda = 0.0;
};

//! The events of one aligned loop pair, in seam order.
struct Alignment {
  double cost = std::numeric_limits<double>::infinity();
  std::vector<SeamEvent> events;
};

//! Aligns closed polylines `first` (m points) and `second` (n points, already running the same way
//! as `first`) by dynamic programming, first[0] welded to second[0]. Every point takes part in
//! exactly one event, events in seam order; a point alone lands on the other loop's current edge,
//! within [min_split, 1 - min_split] of it. Cost: total distance between matched points.
Alignment align_loops(const std::vector<Vec3>& first, const std::vector<Vec3>& second, double min_split);

}  // namespace meshquilt
