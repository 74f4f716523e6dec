#pragma once
//! The order in which synthesis on a surface visits vertices (Turk 2001, Section 5): a sweep
//! along the orienting field, so that each vertex finds its neighbours behind it, in the
//! field's sense, already coloured.

#include <cstdint>
#include <vector>

#include "surface/surface_types.h"

namespace meshquilt {

//! The scalar s over the base's vertices whose gradient follows the field best: the minimizer of
//! sum_f area_f |grad s - d_f|^2 (d_f the mean of the face's vertex directions, projected to its
//! plane), with a vanishing pull of s to 0 that fixes its constant; one sparse solve. Where the
//! field has a singularity s has an extremum, and the sweep starts or ends there.
//! directions  #V unit tangent directions (a guidance field)
//! \throw SolverError when the solve fails.
std::vector<double> sweep_function(const BaseSurface& base, const std::vector<Vec3>& directions);

//! Vertices by increasing `sweep`, ties by index.
std::vector<int32_t> sweep_order(const std::vector<double>& sweep);

}  // namespace meshquilt
