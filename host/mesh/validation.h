#pragma once
//! Checks that a triangle mesh is usable by every stage: faces present, indices in range,
//! finite coordinates, element ids aligned with the faces.

#include <string>

#include "mesh/tri_mesh.h"

namespace meshquilt {

//! Validates `mesh`; `source` names it in messages (a file path or "swatch", "base").
//! \throw InputError(invalid_mesh) "SOURCE: problem" when the mesh has no faces, a vertex index
//!        outside [0, #V), a NaN/Inf coordinate, or `elements` that is neither empty nor #F long
//!        or holds a negative id.
void validate_mesh(const TriMesh& mesh, const std::string& source);

}  // namespace meshquilt
