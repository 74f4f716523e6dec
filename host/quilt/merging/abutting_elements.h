#pragma once
//! Elements that meet face to face. Patches registered exactly place copies of a periodic yarn
//! end to end, so the end cap of one copy lies on the start cap of the next: two closed elements
//! sharing a disk of faces with opposite orientations, which a viewer welding by distance sees
//! as one non-manifold element. Removing both copies of every shared face and welding their
//! vertices makes them one closed yarn.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Joins the elements of `layer` (per-face `elements`, and `sources` when present) that meet face
//! to face: a face of one element whose three corners coincide, within `relative_tolerance` x
//! the layer's bounding-box diagonal, with those of a face of another in the opposite order.
//! Both faces go, the second element's corners weld to the first's, and the group takes the
//! lowest element id of its members; a group whose union would not be a closed 2-manifold is
//! left as it was. Element ids are renumbered to stay consecutive in order of first face;
//! unreferenced vertices are dropped. Returns how many elements were joined into others (0
//! leaves `layer` unchanged). kept_vertices, when given and something was joined: the vertex of
//! the old layer each new vertex is.
int32_t join_abutting_elements(TriMesh& layer, double relative_tolerance, std::vector<int32_t>* kept_vertices = nullptr);

}  // namespace meshquilt
