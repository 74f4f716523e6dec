#pragma once
//! Guidance vector fields over a base (Section 3.1 of the mesh quilting paper; interpolation as in
//! Turk 2001, Section 4.1): a few user directions spread smoothly over the surface, tangent and
//! unit length, that orient the swatch in every patch.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/tri_mesh.h"
#include "surface/conformal_patch.h"

namespace meshquilt {

//! One user direction at a base vertex (or at the vertex nearest a surface point).
struct FieldConstraint {
  int32_t vertex = -1;
  Vec3 direction{1.0, 0.0, 0.0};
};

//! Parses the text of a field file: JSON `{"directions": [{"vertex": 12, "direction": [x, y, z]},
//! {"point": [x, y, z], "direction": [x, y, z]}, ...]}`; a `point` goes to the nearest base vertex.
//! `name` (the file) starts every message.
//! \throw InputError(invalid_option) "NAME: problem" for malformed JSON, a missing or non-numeric
//!        direction, a zero or non-finite direction, a vertex that does not exist, or a point on a
//!        base without vertices.
std::vector<FieldConstraint> parse_field(std::string_view text, const std::string& name, const TriMesh& base);

//! Directions given at surface points (a stroke drawn over the base), each at the base vertex
//! nearest its point, as a field file's `point` entries are. `name` starts every message.
//! \throw InputError(invalid_option) "NAME: problem" for counts that differ, a non-finite point
//!        or direction, a zero direction, or a base without vertices.
std::vector<FieldConstraint> constraints_at_points(const std::vector<Vec3>& points, const std::vector<Vec3>& directions,
                                                  const TriMesh& base, const std::string& name);

//! Reads a field file and parses it with parse_field.
//! \throw IoError(file_unreadable) when the file cannot be read; what parse_field throws.
std::vector<FieldConstraint> read_field_file(const std::filesystem::path& file, const TriMesh& base);

//! A unit tangent direction per base vertex.
struct GuidanceField {
  std::vector<Vec3> directions;  //!< #V
  Vec3 axis{1.0, 0.0, 0.0};      //!< the default field's axis (see interpolate_field)
  std::vector<int32_t> held_vertices;  //!< vertices whose direction a constraint gives

  //! The field at a surface point: interpolated, projected to the face's plane, unit length (any
  //! unit tangent of the face where the interpolation vanishes: at a singularity).
  Vec3 at(const BaseSurface& base, const SurfacePoint& p) const;
};

//! Spreads the constraints over the base: directions d_v, each in its vertex's tangent plane,
//! minimize the sum over edges of |d_v - d_w|^2 (Turk's diffusion with tangent-plane projection,
//! solved at once: two unknowns per vertex, one sparse solve) with the constrained vertices held at
//! their directions' unit tangent parts (a direction's length does not matter), plus a weak pull
//! (weight `regularization`) toward the default field; each is then normalized. Directions spread
//! along the surface, not through space: two given on opposite sides of a body, both running round
//! it, agree (a vector Laplacian in space would average them to nothing halfway round).
//! The default field (all of it without constraints, and what unconstrained components follow) is
//! the base's principal axis (largest variance of its area-weighted vertices) projected to each
//! tangent plane: smooth and coherent, it runs along the object's length, and its singularities
//! are where the normal is parallel to the axis (the two ends of a sphere or a blob; on a genus-g
//! surface also saddles, index sum 2 - 2g as Poincare-Hopf demands).
//! \throw SolverError when the solve fails.
GuidanceField interpolate_field(const BaseSurface& base, const std::vector<FieldConstraint>& constraints,
                                double regularization = 1e-3);

//! Writes the field as OBJ line segments, one per face from its centroid along the field (length
//! `length`), which Blender and other DCCs show as edges. \throw IoError(write_failed).
void write_field_obj(const BaseSurface& base, const GuidanceField& field, double length,
                     const std::filesystem::path& file);

}  // namespace meshquilt
