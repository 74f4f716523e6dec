#pragma once
//! Field-aligned charts of surface patches: a patch flattened so that the plane's x axis follows
//! the guidance field and lengths stay base lengths, face by face as far as the field allows. Two
//! overlapping patches of one smooth field then differ, on their overlap, by about a translation,
//! which is all that geometry matching searches (a conformal map per patch, turned to the field
//! at its seed alone, differs from its neighbour's by a rotation and a scale as well).

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "surface/surface_types.h"

namespace meshquilt {

//! The least-squares solution of grad u = d_f, grad v = n_f x d_f over the faces (area weighted:
//! one Poisson solve with two right-hand sides, the first corner of the first face held at 0),
//! where d_f is the unit field direction of face f in its plane.
//! faces          base faces (zero-area ones add nothing)
//! corner_vertex  3 x #faces local vertex index of each corner
//! vertex_base    #local vertices, the base vertex of each
//! face_field     #base faces, a tangent direction per face (need not be unit)
//! Returns #local vertices plane coordinates in base units.
//! \throw SolverError when the system cannot be solved.
std::vector<glm::dvec2> field_aligned_flattening(const BaseSurface& base, const std::vector<int32_t>& faces,
                                                 const std::vector<int32_t>& corner_vertex,
                                                 const std::vector<int32_t>& vertex_base,
                                                 const std::vector<Vec3>& face_field);

}  // namespace meshquilt
