#pragma once
//! Base meshes as they come (Section 3 of the mesh quilting paper works on "arbitrary" surfaces):
//! welded, checked for a manifold surface, and oriented consistently.

#include <string>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Returns `mesh` ready to carry a texture: coincident vertices welded (kWeldTolerance), faces
//! that collapse dropped, each connected component's faces oriented consistently (flipped by a
//! breadth-first walk from its first face) and outward: for a closed component a positive signed
//! volume, for an open one a positive volume of the cone from its area centroid (a scan open at
//! the neck faces out); an open component flat to within 1e-3 of its area x radius keeps the
//! orientation of its first face. Open components, several components and any genus are
//! accepted. `elements` is cleared. `source` names the mesh in messages.
//! \throw InputError(invalid_mesh) "SOURCE: problem" for no faces, NaN/Inf, indices out of range,
//!        an edge shared by more than two faces after welding, or a non-orientable component.
TriMesh prepare_base(const TriMesh& mesh, const std::string& source);

}  // namespace meshquilt
