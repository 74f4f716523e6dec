#pragma once
//! Base meshes as they come (Section 3 of the mesh quilting paper works on "arbitrary" surfaces):
//! welded, checked for a manifold surface, and oriented consistently.

#include <string>
#include <vector>

#include "mesh/mesh_repair.h"
#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Returns `mesh` ready to carry a texture: repaired by repair_mesh (welded, unused vertices and
//! collapsed, duplicate and zero-area faces dropped, T-junctions closed, pinched vertices split,
//! each part wound coherently and outward), its `repairs` stored when asked. Open components,
//! several components and any genus are accepted. `elements` is cleared. `source` names the mesh
//! in messages.
//! \throw InputError(invalid_mesh) "SOURCE: problem" for repair_mesh's refusals, a mesh whose
//!        faces all lie on lines, and a part lying more than 10 of its diagonals away from the
//!        largest part (a stray face an exporter left).
TriMesh prepare_base(const TriMesh& mesh, const std::string& source, MeshRepairs* repairs = nullptr);

//! For each vertex of prepare_base(mesh), the raw vertex of `mesh` it came from (the earliest of
//! those welded into it), so that later frames of an animated base (same raw vertices and faces)
//! can be posed on the prepared connectivity without welding them again: see posed_base.
std::vector<int32_t> prepared_vertex_sources(const TriMesh& mesh);

//! `prepared` (prepare_base of a reference frame) with its vertices moved to where `frame` puts
//! their raw vertices (`sources` from prepared_vertex_sources of the reference frame).
TriMesh posed_base(const TriMesh& prepared, const std::vector<int32_t>& sources, const TriMesh& frame);

}  // namespace meshquilt
