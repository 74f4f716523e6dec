#pragma once
//! Closing a ring mail round a cone of the layout, as a mail maker closes a sheet round a point:
//! where the lattice turns by a half turn about a point, the rings there cannot all link as many
//! as the pattern's do. Rings near the cone that pass through others, or link more than one
//! neighbour over the pattern's count, are taken out; then, while a ring there links two or more
//! fewer than the pattern's count, rings are added one at a time where one links at least one
//! fewer than that count, joins such a ring and another under the count, and takes no ring over
//! one more. A ring linked to one neighbour fewer or one more is how a mail closes round a point.

#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! A ring by its closed centre line in space.
struct ClosureRing {
  std::vector<Vec3> line;
  Vec3 centre{0.0};   //!< mean of the line's points
  double reach = 0.0; //!< largest distance of a line point from centre
};

//! The ring of a closed centre line.
ClosureRing closure_ring(std::vector<Vec3> line);

struct ClosureOptions {
  int links = 4;           //!< links of a ring inside the pattern
  double clearance = 0.0;  //!< least distance of two rings' centre lines: twice the wire's radius
  int max_added = 8;
};

struct ClosurePlan {
  std::vector<int32_t> removed;  //!< rings taken out, indices into the rings given
  std::vector<int32_t> added;    //!< candidates added, in order
  //! Rings of the core linked to fewer than links - 1 others (or meeting one), before and after.
  int short_before = 0, short_after = 0;
};

//! Least distance between the closed polylines a and b.
double centre_line_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

//! The rings that may be added, given which of the rings given are kept (1) once some are taken out.
using ClosureCandidates = std::function<std::vector<ClosureRing>(const std::vector<uint8_t>& kept)>;

//! rings: every ring near the cone; core: 1 for those that may be taken out and whose links count
//! (every ring linked to a core ring must be among `rings`); candidates: asked once, after the
//! rings are taken out; `added` indexes what they return.
ClosurePlan plan_closure(const std::vector<ClosureRing>& rings, const std::vector<uint8_t>& core,
                         const ClosureCandidates& candidates, const ClosureOptions& options);

}  // namespace meshquilt
