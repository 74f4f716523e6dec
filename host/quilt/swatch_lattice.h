#pragma once
//! The translations that map a swatch's pattern onto itself, where it repeats: a surface layout
//! whose seams continue by such translations (and by the turns of swatch_symmetry.h about a
//! centre the pattern turns about) carries the pattern across them unbroken.

#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "quilt/patch_step.h"

namespace meshquilt {

struct SwatchLattice {
  std::array<glm::dvec2, 2> basis{};  //!< the two shortest independent periods, swatch units
  //! A point the pattern turns about through 2 pi / symmetry (any point where symmetry is 1).
  glm::dvec2 centre{0.0};
};

//! The lattice of the swatch's element centroids, when the pattern repeats along two directions:
//! a period maps at least 90% of the elements whose translate lies among the centroids onto an
//! element of the same kind (ElementShape), and does so for at least a quarter of them. Where the
//! centroids show none (a yarn moved by a period lies along another, not on its centroid), the
//! steps between centroids of one kind that put at least 90% of sampled surface points back on
//! the surface. With symmetry > 1, the pattern must also turn through 2 pi / symmetry about some
//! centre, and the turn must map the lattice onto itself. Empty otherwise (scattered fruit).
std::optional<SwatchLattice> swatch_lattice(const QuiltSwatch& swatch, int symmetry);

//! p in the lattice's coordinates: p = k.x basis[0] + k.y basis[1].
glm::dvec2 lattice_coordinates(const glm::dvec2& p, const std::array<glm::dvec2, 2>& basis);

//! The period of the lattice `basis` nearest to p. A point halfway between two periods (as on a
//! symmetric base) goes to the upper one by a margin above rounding noise, so that it goes the
//! same way whatever the floating-point environment.
glm::dvec2 nearest_period(const glm::dvec2& p, const std::array<glm::dvec2, 2>& basis);

//! The translations t within the bounding box of `candidates` for which t + shift is a period of
//! `basis` (within `slack` of the box); where none lies within, the one whose t + shift is the
//! period nearest the box's centre. Empty where the box holds more than 1e5 periods (a lattice
//! finer than the placements it would choose among).
std::vector<glm::dvec2> lattice_placements(const std::vector<glm::dvec2>& candidates, const glm::dvec2& shift,
                                           const std::array<glm::dvec2, 2>& basis, double slack);

}  // namespace meshquilt
