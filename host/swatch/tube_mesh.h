#pragma once
//! Triangulated tubes swept along a centreline: the building block of rings and yarns.

#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! How a swept tube ends.
enum class TubeEnds {
  loop,    //!< the centreline is a closed loop (a torus-like ring); no caps
  capped,  //!< open centreline; each end closed by a flat fan around a centre vertex
};

//! Appends a tube of circular cross-section to `mesh` as one closed 2-manifold with outward
//! orientation, setting `element` as the element id of its faces.
//! centre   #K centreline points (K >= 3 for a loop, K >= 2 when capped); for a loop the last
//!          point connects back to the first (do not repeat it)
//! normal   #K unit vectors perpendicular to the centreline tangent at each point; the
//!          cross-section circle at point k is centre[k] + radius (cos a normal[k] + sin a
//!          binormal[k]) with binormal = tangent x normal
//! sides    vertices per cross-section (>= 3)
//! tangent  #K centreline tangents, or empty for central differences (one-sided at open
//!          ends); give exact ones when the tube must continue seamlessly past a capped end
//! Adds K*sides (+2 when capped) vertices and 2*K*sides (loop) or 2*(K-1)*sides + 2*sides
//! (capped) faces. Precondition: the swept circles do not intersect each other (radius below the
//! centreline's radius of curvature); not checked.
void append_tube(TriMesh& mesh, const std::vector<Vec3>& centre, const std::vector<Vec3>& normal,
                 double radius, int sides, TubeEnds ends, int32_t element,
                 const std::vector<Vec3>& tangent = {});

}  // namespace meshquilt
