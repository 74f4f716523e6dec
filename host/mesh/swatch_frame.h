#pragma once
//! The swatch's own frame (Section 2.1 of the mesh quilting paper; DESIGN "Swatch frame"): the
//! swatch lies in the x-y plane and its height h_in runs along +z.

#include <string>

#include "mesh/mesh_repair.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Returns `swatch` repaired (repair_mesh: welded, bad faces dropped, T-junctions closed, each
//! element wound coherently and outward; the counts stored in `repairs` when asked), turned so
//! its thinnest bounding-box axis becomes z, and moved so its bounding-box minimum is the origin.
//! The turn is a proper rotation (a cyclic permutation of the axes), so triangle orientation and
//! the sign of enclosed volumes are kept. Ties keep z, then prefer x over y as the height axis.
//! `elements` follows the faces. `source` names the swatch in messages.
//! \throw InputError(invalid_mesh) "SOURCE: problem" for repair_mesh's refusals, and
//!        "SOURCE: degenerate swatch: ..." when the thickness is below 1e-9 x the bounding-box
//!        diagonal, an x-y extent is zero, or check_swatch_proportions refuses it.
TriMesh orient_swatch(const TriMesh& swatch, const std::string& source, MeshRepairs* repairs = nullptr);

//! Largest coordinate magnitude a swatch may have.
constexpr double kMaxSwatchCoordinate = 1e15;
//! Largest ratio of the longer to the shorter x-y extent of a swatch.
constexpr double kMaxSwatchAspect = 1000.0;
//! A swatch's bounding-box diagonal may be at most this x sqrt(#F) median edge lengths.
constexpr double kStrayVertexFactor = 100.0;

//! Refuses a swatch whose proportions are absurd for its face count, before its extent turns
//! into billions of grid cells or float overflow: a coordinate beyond kMaxSwatchCoordinate, an
//! x-y aspect above kMaxSwatchAspect, or a bounding box more than kStrayVertexFactor x sqrt(#F)
//! median edge lengths across (a stray vertex). Called by orient_swatch.
//! \pre validate_mesh passed. \throw InputError(invalid_mesh) "SOURCE: degenerate swatch: ..."
//!      naming the extents or the farthest vertex.
void check_swatch_proportions(const TriMesh& swatch, const std::string& source);

//! Index (0 = x, 1 = y, 2 = z) of the axis orient_swatch takes as the height, for a bounding box
//! of extents `extent` (ties keep z, then x before y).
int thinnest_axis(const Vec3& extent);

}  // namespace meshquilt
