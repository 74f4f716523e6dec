#pragma once
//! Coherent patches of sample positions made rigid. Synthesis on a coarse level chooses each
//! vertex's sample position from its neighbours' proposals, which agree only to a fraction of a
//! pixel there; carried to each finer level those fractions double, and a patch copied from the
//! sample comes out stretched and jittered, which every window over it reads. Here each patch
//! (vertices joined by edges whose positions agree with the edge's offset to within `cut`
//! pixels) takes the least-squares positions whose differences along its edges are those
//! offsets, read in the field's frames: rigid where the field allows, bent evenly where it turns.

#include <vector>

#include <glm/vec2.hpp>

#include "surface/surface_types.h"

namespace meshquilt {

//! `sources` (#V, pixels of a sample `period` wide and high, wrapped round it) made rigid per
//! patch over `surface`, whose frames are x along `directions` (#V, unit, tangent) and y along
//! normal x direction, at `pixels_per_unit`. Edges that disagree by more than `cut` pixels are
//! seams and stay so; each vertex is held to where it was with weight `hold` (> 0) against one
//! per edge, which fixes each patch's place. Returns the positions wrapped into the sample.
//! \throw SolverError when the solve fails.
std::vector<glm::dvec2> rigid_sources(const BaseSurface& surface, const std::vector<Vec3>& directions,
                                      double pixels_per_unit, const glm::dvec2& period,
                                      const std::vector<glm::dvec2>& sources, double cut, double hold = 1e-3);

}  // namespace meshquilt
