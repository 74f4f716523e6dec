#pragma once
//! The swatch's own frame (Section 2.1 of the mesh quilting paper; DESIGN "Swatch frame"): the
//! swatch lies in the x-y plane and its height h_in runs along +z.

#include <string>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Returns `swatch` turned so its thinnest bounding-box axis becomes z, and moved so its
//! bounding-box minimum is the origin. The turn is a proper rotation (a cyclic permutation of the
//! axes), so triangle orientation and the sign of enclosed volumes are kept. Ties keep z, then
//! prefer x over y as the height axis. `elements` is copied unchanged.
//! `source` names the swatch in messages.
//! \throw InputError(invalid_mesh) "SOURCE: problem" when validate_mesh fails, and
//!        "SOURCE: degenerate swatch: ..." when the thickness is below 1e-9 x the bounding-box
//!        diagonal or an x-y extent is zero.
TriMesh orient_swatch(const TriMesh& swatch, const std::string& source);

//! Index (0 = x, 1 = y, 2 = z) of the axis orient_swatch takes as the height, for a bounding box
//! of extents `extent` (ties keep z, then x before y).
int thinnest_axis(const Vec3& extent);

}  // namespace meshquilt
