#pragma once
//! Elements of a swatch cut open by its border: a mail or a weave cropped from a larger sheet
//! through its elements, whichever way the crop was turned.

#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Per element, 1 where it is open and its rim (the edges of one face) comes within one and a
//! half rim edges of the boundary of the x-y convex hull of all the elements' vertices: the
//! crop went through it. Closed elements and open ones inside the footprint give 0.
std::vector<uint8_t> cut_by_border(const std::vector<TriMesh>& elements);

}  // namespace meshquilt
