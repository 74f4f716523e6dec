#pragma once
//! Base meshes as they come (Section 3 of the mesh quilting paper works on "arbitrary" surfaces):
//! welded, checked for a manifold surface, and oriented consistently.

#include <string>
#include <vector>

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

//! For each vertex of prepare_base(mesh), the raw vertex of `mesh` it came from (the earliest of
//! those welded into it), so that later frames of an animated base (same raw vertices and faces)
//! can be posed on the prepared connectivity without welding them again: see posed_base.
std::vector<int32_t> prepared_vertex_sources(const TriMesh& mesh);

//! `prepared` (prepare_base of a reference frame) with its vertices moved to where `frame` puts
//! their raw vertices (`sources` from prepared_vertex_sources of the reference frame).
TriMesh posed_base(const TriMesh& prepared, const std::vector<int32_t>& sources, const TriMesh& frame);

}  // namespace meshquilt
