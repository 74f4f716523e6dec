#pragma once
//! A direction field for a closed base of genus 0 or a disc that no user drew: cones placed where
//! they flatten the base most evenly (a disc's border keeping its lengths), and the field parallel in the flat metric with those cones
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
//! defect): mean 0 over a closed base, where K_hat sums to the total angle defect; 0 on a disc's
//! border, where K_hat is read at interior vertices only.
//! \throw SolverError when the solve fails.
std::vector<double> cone_metric_scale(const BaseSurface& base, const std::vector<double>& target_curvature);

//! exp(p90 - p10) of phi, weighted by vertex area: how far lengths in the metric spread.
double scale_spread(const BaseSurface& base, const std::vector<double>& phi);

//! The scale spread of the flat metric with a cone of index[v] / symmetry at each vertex v.
//! std::nullopt where the base is neither one closed component of genus 0 nor one disc.
std::optional<double> cone_scale_spread(const BaseSurface& base, const std::vector<int>& index, int symmetry);

//! cone_scale_spread at the field's singularities (field_indices).
std::optional<double> field_scale_spread(const BaseSurface& base, const DirectionField& field);

//! The default bound on the layout's scale spread: #65's element sizes, p90 / p10 = 1.25 / 0.8.
inline constexpr double kDefaultConeSpread = 1.5625;

//! How far the cone metric may scale lengths, and what more cones may cost.
struct ConeBound {
  double spread = kDefaultConeSpread;  //!< cones are added while scale_spread exceeds this
  double separation = 0.0;             //!< no cone nearer another than this, in base units
  int max_pairs = 0;                   //!< 0: a sphere's 2n cones alone, a disc's none
};

//! The field of symmetry n parallel in the cone metric, its 2n cones of index 1 / n placed
//! greedily, each at the lowest scale left by the cones so far with the rest of the curvature
//! spread evenly, then moved two at a time while that narrows the scale's spread (on a sphere:
//! from two opposite pairs a quarter turn apart to about a tetrahedron's corners); then, while
//! the spread exceeds `bound.spread`, up to `bound.max_pairs` pairs of cones of index -1 / n
//! and 1 / n where lengths in the metric are longest and shortest (Ben-Chen et al. 2008's
//! greedy choice, in whole cones); every cone `bound.separation` from every other; the first
//! placement within the bound is kept, or else the one that spreads least. On a disc no cone is
//! owed: up to 2 x `bound.max_pairs` cones one at a time, each of the sign that narrows the
//! spread more, the same way. Turned so that `root_direction` holds on face 0.
//! std::nullopt where the base is neither one closed component of genus 0 nor one disc.
//! \throw SolverError when a solve fails.
std::optional<DirectionField> cone_metric_field(const BaseSurface& base, int symmetry, const Vec3& root_direction,
                                                const ConeBound& bound = {});

}  // namespace meshquilt
