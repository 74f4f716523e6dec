#pragma once
//! A direction field for a closed base of genus 0 that no user drew: cones placed where they
//! flatten the base most evenly, and the field parallel in the flat metric with those cones
//! (a trivial connection, Crane et al. 2010, with the metric's conformal scale from the
//! linearized curvature prescription of Ben-Chen et al. 2008). On a round sphere every line field
//! of the smoothest eigenspace is as smooth as another, so the smoothest field keeps whatever cone
//! placement the weak pull to the guidance field suggests (the axis projection's poles, pairing
//! the four cones there); the cone metric tells placements apart by how evenly they scale.

#include <optional>
#include <vector>

#include "surface/direction_field.h"

namespace meshquilt {

//! The log scale factor per vertex solving L phi = K_hat - K (L the cotan Laplacian, K the angle
//! defect), mean 0. \pre the base is closed, K_hat sums to the total angle defect.
//! \throw SolverError when the solve fails.
std::vector<double> cone_metric_scale(const BaseSurface& base, const std::vector<double>& target_curvature);

//! exp(p90 - p10) of phi, weighted by vertex area: how far lengths in the metric spread.
double scale_spread(const BaseSurface& base, const std::vector<double>& phi);

//! The scale spread of the flat metric whose cones are the field's singularities.
//! std::nullopt where the base is not one closed component of genus 0.
std::optional<double> field_scale_spread(const BaseSurface& base, const DirectionField& field);

//! The field of symmetry n parallel in the cone metric, its 2n cones of index 1 / n placed
//! greedily, each at the lowest scale left by the cones so far with the rest of the curvature
//! spread evenly, then moved two at a time while that narrows the scale's spread (on a sphere:
//! from two opposite pairs a quarter turn apart to about a tetrahedron's corners), turned so
//! that `root_direction` holds on face 0.
//! std::nullopt where the base is not one closed component of genus 0.
//! \throw SolverError when a solve fails.
std::optional<DirectionField> cone_metric_field(const BaseSurface& base, int symmetry, const Vec3& root_direction);

}  // namespace meshquilt
