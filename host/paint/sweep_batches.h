#pragma once
//! The parallel scheme of synthesis on surfaces. Turk's sweep colours one vertex after another,
//! each reading the vertices within its window; two vertices whose windows do not reach each
//! other can be coloured at once. Each vertex goes into the first batch after those of the
//! window neighbours before it in the sweep (and not before a batch of one whose window holds
//! it), so every vertex reads exactly the state the sequential sweep would have shown it: the
//! batches, run in turn with their vertices side by side, give the sweep's result.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "surface/surface_types.h"

namespace meshquilt {

//! The vertices within `radius` of each vertex (by distance in space, reached through edges
//! without leaving that ball), the vertex itself left out: vertices[first[v], first[v + 1]).
struct WindowNeighbours {
  std::vector<int64_t> first;    //!< #V + 1
  std::vector<int32_t> vertices;
};

WindowNeighbours window_neighbours(const BaseSurface& surface, double radius);

//! `order` (a permutation of the vertices) cut into batches as above, each in sweep order and at
//! most `max_batch` long (a longer batch is split). max_batch == 1 gives the sweep itself.
std::vector<std::vector<int32_t>> sweep_batches(const std::vector<int32_t>& order, const WindowNeighbours& windows,
                                                size_t max_batch);

}  // namespace meshquilt
