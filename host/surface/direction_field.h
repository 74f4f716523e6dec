#pragma once
//! Smoothest n-direction fields on a base (Knoppel et al. 2013, "Globally optimal direction
//! fields"): per face, n directions 2 pi / n apart, represented by the power u = z^n, so that the
//! field is one linear solve and its singularities fall where smoothness puts them.

#include <cstdint>
#include <vector>

#include "surface/guidance_field.h"
#include "surface/surface_types.h"

namespace meshquilt {

//! An n-direction field: per face one of its n unit tangent directions (any of them).
struct DirectionField {
  int symmetry = 1;              //!< n: 1 (vector field), 2 (line field) or 4 (cross field)
  std::vector<Vec3> directions;  //!< #F unit tangents (an arbitrary unit tangent on a zero-area face)
};

//! The n-direction field u minimizing sum over interior edges |u_g - r_fg u_f|^2 (r_fg: the
//! power-n parallel transport across the shared edge) + sum over faces w_f a_f |u_f - q_f|^2,
//! where a_f is the face's area over the mean face area and q_f the power of target_f. With w_f
//! tiny everywhere this is the smoothest field (the target only picks among equally smooth ones);
//! with w_f large on some faces the field holds the target there and is smoothest in between.
//! target  #F tangent directions (length ignored; a zero vector asks for nothing)
//! weight  #F, w_f >= 0
//! \throw SolverError when the solve fails.
DirectionField smoothest_direction_field(const BaseSurface& base, int symmetry, const std::vector<Vec3>& target,
                                         const std::vector<double>& weight);

//! The weight of a face that holds no user direction: small against an edge's, so the field is
//! the smoothest one of the base, but never zero, so every component has a definite field.
double default_field_weight(const BaseSurface& base);

//! The weight of every face when the user drew a field: large against the smoothest field's
//! first eigenvalue, so the field follows the drawn one and only smooths it (wefts over the
//! bunny with data/bunny_field.json: 8.9 degrees from it where it turns slowly, against 13.5 with
//! the default weight).
double guided_field_weight(const BaseSurface& base);

//! What the smoothest field is asked to hold for a guidance field: its direction at each face's
//! centroid, weighted as a drawn field (guided_field_weight, and 10 round a given direction's
//! vertex) or as the default one (default_field_weight), which only picks among the smoothest.
struct FieldTargets {
  std::vector<Vec3> target;    //!< #F
  std::vector<double> weight;  //!< #F
};

FieldTargets field_targets(const BaseSurface& base, const GuidanceField& guidance);

//! A tangent direction of face f carried across its edge (a, b) into face g: the same angle to the
//! edge, in g's plane (discrete parallel transport: unfolding g into f's plane).
Vec3 transport_across(const BaseSurface& base, int32_t f, int32_t g, int32_t a, int32_t b, const Vec3& d);

//! The angle that turns `from` onto `to` about `normal`, in (-pi, pi] (both tangent to it).
double signed_angle(const Vec3& from, const Vec3& to, const Vec3& normal);

//! The index of the field at every vertex in units of 1 / n (0 at a boundary vertex): the turn
//! of the field against parallel transport around the vertex plus its angle defect, over 2 pi / n.
//! Indices of a closed surface sum to n times its Euler characteristic (Poincare-Hopf).
std::vector<int> field_indices(const BaseSurface& base, const DirectionField& field);

}  // namespace meshquilt
